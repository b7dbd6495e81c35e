#pragma once
/// @file StreamoutPassInputs.h
/// What each of streamout's passes records with: the frame, the terrain, this
/// frame slot's intermediate buffers, the draw's tessellation uniforms and a
/// way to push the terrain's shared bindings (which BasicTerrainBackend owns).

#include "common/GpuTerrain.h"
#include "StreamoutBuffers.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <functional>
#include <span>

namespace tessera::backends {

struct StreamoutPassInputs {
    /// Pushes the frame, terrain and height-map bindings plus `extra` for a layout.
    using PushBindings = std::function<void(const gpu::PipelineLayout&, std::span<const VkWriteDescriptorSet>)>;

    gpu::FrameContext& frame;
    GpuTerrain& terrain;
    StreamoutBuffers::Slot& buffers;
    /// shader::TerrainTessUniforms of this draw.
    gpu::UniformSlice tessUniforms;
    PushBindings pushBindings;
};

} // namespace tessera::backends
