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
/// `resolution` texels on a side. Receivers are offset along their normal
/// by `normalOffsetTexels` texels of their cascade and compared
/// `depthBiasMetres` nearer the sun, against acne on surfaces facing away
/// from the sun's rays. No cascades: params.x is 0 (no cascaded shadows).
shader::ShadowCascadeUniforms buildShadowCascadeUniforms(std::span<const ShadowCascade> cascades,
                                                         uint32_t resolution, float normalOffsetTexels = 1.5f,
                                                         float depthBiasMetres = 0.05f);

} // namespace tessera::scene
