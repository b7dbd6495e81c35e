#pragma once
/// @file ComputeTessFactorPass.h
/// The factor pre-pass of the backends with compute (hulldomain,
/// meshshader): a dispatch that writes one level per canonical control-mesh
/// edge and per patch (terrain_factors.comp), the D3D11 way of moving the
/// metric out of the hull shader so each shared edge is evaluated once and
/// both patches read the same bits.

#include "common/GpuTerrain.h"
#include "common/TerrainBindings.h"
#include "tessera/shaders/TessFactors.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <string>

namespace tessera::backends {

class ComputeTessFactorPass {
public:
    ComputeTessFactorPass() = default;
    ComputeTessFactorPass(gpu::Device& device, const std::string& backendName);

    /// Records "terrain.factors": levels for every edge and patch of `terrain`
    /// into the slot's level buffers, then a barrier that makes them visible
    /// to `reader`, the stage that reads them (tessellation control, task).
    void record(gpu::FrameContext& frame, GpuTerrain& terrain, const gpu::UniformSlice& tessUniforms,
                const PushTerrainBindings& pushBindings, VkPipelineStageFlags2 reader);

private:
    gpu::PipelineLayout mLayout;
    gpu::ComputePipeline mPipeline;
};

} // namespace tessera::backends
