#pragma once
/// @file StreamoutPassInputs.h
/// What each of streamout's passes records with: the frame, the terrain, this
/// frame slot's intermediate buffers, the draw's tessellation uniforms and a
/// way to push the terrain's shared bindings (which BasicTerrainBackend owns).

#include "common/GpuTerrain.h"
#include "common/TerrainBindings.h"
#include "StreamoutBuffers.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

struct StreamoutPassInputs {
    gpu::FrameContext& frame;
    GpuTerrain& terrain;
    StreamoutBuffers::Slot& buffers;
    /// shader::TerrainTessUniforms of this draw.
    gpu::UniformSlice tessUniforms;
    /// Pushes the terrain's shared bindings (BasicTerrainBackend::terrainPush).
    PushTerrainBindings pushBindings;
};

} // namespace tessera::backends
