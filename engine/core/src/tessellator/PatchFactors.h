#pragma once
// The levels of one patch as the reference tessellator sees them after its
// first stage: culling, clamping per partitioning, rounding, parity, the
// "picture frame" rule for fractional_odd, and conversion to 16.16.

#include "EdgeSpacing.h"

#include "tessera/tessellator/TessellationTypes.h"

#include <array>

namespace tessera::tessellator::detail {

class PatchFactors {
public:
    PatchFactors(Domain domain, Partitioning partitioning, const TessFactors& factors);

    Domain domain() const { return mDomain; }
    int edgeCount() const { return mDomain == Domain::Quad ? 4 : 3; }

    /// An outer level was <= 0 or NaN: the patch produces nothing.
    bool culled() const { return mCulled; }
    /// Every level is exactly 1 (integer or fractional_odd): one triangle, or
    /// the two triangles of the quad, with no rings.
    bool minimal() const { return mMinimal; }

    /// Outer edge `edge` in D3D11/Vulkan order (see TessFactors).
    const EdgeSpacing& outer(int edge) const { return mOuter[static_cast<size_t>(edge)]; }
    /// Inner axis (quad: 0 = u, 1 = v; triangle: 0 only).
    const EdgeSpacing& inner(int axis) const { return mInner[static_cast<size_t>(axis)]; }
    /// Points across the inner axis, raised to 3 (even) or 4 (odd) so that
    /// there is always a first ring, even if it is degenerate.
    int innerPoints(int axis) const { return mInnerPoints[static_cast<size_t>(axis)]; }

private:
    Domain mDomain;
    bool mCulled = false;
    bool mMinimal = false;
    std::array<EdgeSpacing, 4> mOuter{};
    std::array<EdgeSpacing, 2> mInner{};
    std::array<int, 2> mInnerPoints{};
};

} // namespace tessera::tessellator::detail
