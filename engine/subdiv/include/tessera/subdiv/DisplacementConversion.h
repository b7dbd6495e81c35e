#pragma once
/// @file DisplacementConversion.h
/// A traditional displacement (a value per surface point) into the tile
/// format (Niessner and Loop, section 4.1: "we resample the displacement
/// map and solve for the biquadratic B-spline coefficients to interpolate
/// the displacement data").
///
/// Samples are taken at every tile's level-0 texel centres, ((x, y) + 0.5)
/// / tileSize, one per coefficient. A tile's spline there depends on its
/// overlaps, which are its neighbours' coefficients, so the tiles' solves
/// are coupled: each round solves every tile exactly (TileInterpolator:
/// tridiagonal solves) with the overlaps of the previous round, then
/// rederives the texture; a neighbour's influence on a tile's first row is
/// about 0.17 of a coefficient, so the rounds converge geometrically.
/// At an extraordinary fan the format fixes the corner blocks to one value
/// (section 4.2): the conversion sets it to the mean of the samples at the
/// vertex itself (D there is that value) and drops the samples at those
/// corner texels, which the spline then misses; every other sample is
/// interpolated to the tolerance.

#include "tessera/subdiv/DisplacementTiles.h"

#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// The displacement to convert, at (ptex face, u, v).
using DisplacementSampler = std::function<double(uint32_t ptexFace, glm::dvec2 uv)>;

struct ConversionOptions {
    uint32_t maxRounds = 100;
    /// Stop when no coefficient moves by more than this times the largest
    /// sample magnitude in a round.
    double tolerance = 1e-6;
};

struct ConversionReport {
    uint32_t rounds = 0;
    bool converged = false;
    size_t samples = 0;       ///< interpolated samples
    size_t pinnedSamples = 0; ///< samples at extraordinary corner texels (not interpolated)
    double sampleScale = 0.0; ///< largest |sample|
    /// Worst |D - sample| at the interpolated samples (level 0, through the
    /// shared lookup in float), and at the pinned ones.
    double maxResidual = 0.0;
    double maxPinnedResidual = 0.0;
};

/// Sets every coefficient of `tiles` from `sample` and rederives the
/// texture. Hole tiles are sampled too (the sampler may return anything
/// there; nothing else reads them).
ConversionReport convertDisplacement(DisplacementTiles& tiles, const DisplacementSampler& sample,
                                     const ConversionOptions& options = {});

} // namespace tessera::subdiv
