#pragma once
/// @file FrameUniformsBuilder.h
/// Fills the shared FrameUniforms layout from the contract's FrameInfo.

#include "tessera/shaders/FrameUniforms.h"
#include "tessera/backend/FrameInfo.h"

namespace tessera::backends {

shader::FrameUniforms buildFrameUniforms(const backend::FrameInfo& frame);

} // namespace tessera::backends
