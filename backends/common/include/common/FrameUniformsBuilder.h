#pragma once
/// @file FrameUniformsBuilder.h
/// Fills the shared FrameUniforms layout from the contract's FrameInfo.

#include "tessera/shaders/FrameUniforms.h"
#include "tessera/backend/FrameInfo.h"

namespace tessera::backends {

/// `terrainDeferred`: in the full look, the terrain's main-pass fragments
/// only mark coverage and the terrain resolve pass shades them
/// (FrameUniforms::terrainResolve.x); false draws a terrain shaded forward.
shader::FrameUniforms buildFrameUniforms(const backend::FrameInfo& frame, bool terrainDeferred = true);

} // namespace tessera::backends
