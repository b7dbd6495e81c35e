#pragma once
// Internal: the upwind (Godunov) update of the eikonal equation on a square
// grid, for the tile solver.

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace tessera::crowd {

/// The upwind update of a cell (Zhao's fast sweeping), with a different
/// cost per axis as continuum crowds needs: `a` reached at cost `ca` (cost
/// times spacing) along one axis, `b` at `cb` along the other, `ia` and `ib`
/// the inverse squares of the costs (precomputed: a tile solve updates each
/// cell a dozen times); the solution of ((u - a) / ca)^2 + ((u - b) / cb)^2
/// = 1 when both are upwind, else the cheaper one-sided value. Solved for
/// u - min(a, b), whose coefficients stay small: in u itself they are the
/// squares of potentials of thousands of metres, and the difference the root
/// needs would be lost to rounding.
inline float eikonalUpdate(float a, float ca, float ia, float b, float cb, float ib) {
    if (a > b) std::swap(a, b), std::swap(ca, cb), std::swap(ia, ib);
    const float oneSided = std::min(a + ca, b + cb);
    if (!(oneSided < std::numeric_limits<float>::infinity()) || oneSided <= b) return oneSided;
    const float d = b - a;
    const float discriminant = ia + ib - ia * ib * d * d;
    if (discriminant < 0.0f) return oneSided;
    return std::min(oneSided, a + (ib * d + std::sqrt(discriminant)) / (ia + ib));
}

} // namespace tessera::crowd
