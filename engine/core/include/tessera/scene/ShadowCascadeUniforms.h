#pragma once
/// @file ShadowCascadeUniforms.h
/// Packs fitted shadow cascades into the layout the shaders read.

#include "tessera/scene/ShadowCascade.h"
#include "tessera/shaders/ShadowCascades.h"

#include <cstdint>
#include <span>

namespace tessera::scene {

/// The shader::ShadowCascadeUniforms of `cascades` (nearest first, at most
/// TS_SHADOW_MAX_CASCADES; more is a programming error) rendered into maps
/// `resolution` texels on a side, read with `pcfTaps` taps on a side (1 to
/// 3). Receivers are offset along their normal by `normalOffsetTexels`
/// texels of their cascade and compared `depthBiasMetres` nearer the sun,
/// against acne on surfaces facing away from the sun's rays. No cascades:
/// params.x is 0 (no cascaded shadows).
shader::ShadowCascadeUniforms buildShadowCascadeUniforms(std::span<const ShadowCascade> cascades,
                                                         uint32_t resolution, uint32_t pcfTaps = 3,
                                                         float normalOffsetTexels = 1.5f,
                                                         float depthBiasMetres = 0.05f);

/// What the casters' depth-only draws of cascade `index` push
/// (shader::ShadowCasterPush): its matrix and its cull per cascade, the
/// slice's view depths (open towards the camera for the first) and how far
/// a caster's shadow reaches under the sun towards `towardsSun` (two radii
/// plus the shadow of a body two radii tall, the sun's elevation taken as
/// at least 1 degree).
shader::ShadowCasterPush buildShadowCasterPush(std::span<const ShadowCascade> cascades, size_t index,
                                               const glm::vec3& towardsSun);

} // namespace tessera::scene
