#pragma once
/// @file TileInterpolator.h
/// The per-tile solve of the conversion from sampled displacement
/// (Niessner and Loop, section 4.1): the interior coefficients of one tile
/// level whose biquadratic spline takes given values at the n x n texel
/// centres, its overlap ring given. At a texel centre the spline is
/// (1, 6, 1) / 8 in each direction, a tensor product, so the solve is two
/// passes of tridiagonal solves (columns, then rows), O(n^2).
///
/// A side whose ring is the linear extrapolation of the tile's own texels
/// (a boundary) is solved with the extrapolation in the equations, where
/// (2 d1 - d2) + 6 d1 + d2 = 8 d1: the first coefficient is its sample.
/// Corner coefficients may be pinned (extraordinary vertices, where the
/// format fixes them): their samples are dropped and replaced by the pinned
/// values, through the solve's response to those samples (at most 4x4).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv::detail {

struct PinnedCoefficient {
    glm::uvec2 texel{1}; ///< 1-based interior corner texel (1 or n)
    double value = 0.0;
};

class TileInterpolator {
public:
    explicit TileInterpolator(uint32_t n) : mN(n) {}

    /// `grid`: the (n+2)^2 level texels, row after row; its ring (overlaps)
    /// is read, its interior replaced by the solution. `samples`: n^2 values
    /// at the interior texel centres, row after row. `extrapolated[e]`: the
    /// ring across tile edge e (0: y = 0, 1: x = n+1, 2: y = n+1, 3: x = 0)
    /// is the linear extrapolation of the interior, corners included.
    void solve(std::span<double> grid, std::span<const double> samples, std::span<const PinnedCoefficient> pins,
               std::array<bool, 4> extrapolated) const;

private:
    /// Solves (z[i-1] + 6 z[i] + z[i+1]) = rhs[i-1], i = 1..n, for z[1..n]:
    /// z[0] (z[n+1]) given, or 2 z[1] - z[2] (2 z[n] - z[n-1]) where `low`
    /// (`high`) is set. `stride` steps between consecutive z.
    void tridiagonal(bool low, bool high, double* z, size_t stride, std::span<double> rhs) const;

    uint32_t mN = 2;
};

} // namespace tessera::subdiv::detail
