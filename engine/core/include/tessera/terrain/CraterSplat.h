#pragma once
/// @file CraterSplat.h
/// A crater stamped into the terrain (the first paper's meteor-shower
/// splats), and its application to the CPU copy of the height field.

#include "tessera/terrain/HeightField.h"
#include "tessera/terrain/SampleRect.h"

#include <glm/vec2.hpp>

namespace tessera::terrain {

/// Shape of a crater; see tsCraterOffset in engine/core/include/tessera/shaders/CraterProfile.h.
struct CraterProfile {
    float depth = 14.0f;     ///< metres below the old ground at the centre
    float rimHeight = 4.0f;  ///< metres above the old ground at the rim
    float rimAt = 0.7f;      ///< rim position as a fraction of the radius, in (0, 1)
};

/// The shape of a crater `radius` metres wide: a bowl 0.22 r deep, about a
/// ninth as deep as it is wide, with a rim 0.06 r high at 0.7 r. Meteor
/// impacts and the host's own craters (the demo's --splat) take it, so every
/// crater has the same shape whatever its size.
CraterProfile scaledCraterProfile(float radius);

/// One splat: a crater of `radius` metres centred at world (x, z) = center.
struct CraterSplat {
    glm::vec2 center{0.0f};
    float radius = 60.0f;
    CraterProfile profile;
};

/// Applies `splat` to the samples of `field` strictly inside its radius with
/// the shared formula (tsCraterDelta, added as an integer, as the GPU splat
/// pass does through an R16_UINT view), and returns the rectangle of samples that
/// may have changed (empty when the crater misses the field). Samples at or
/// beyond the radius are never written.
SampleRect applyCrater(HeightField& field, const CraterSplat& splat);

/// The samples a splat can touch (its radius's bounding square, clamped).
SampleRect craterSamples(const HeightField& field, const CraterSplat& splat);

} // namespace tessera::terrain
