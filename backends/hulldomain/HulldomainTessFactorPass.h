#pragma once
/// @file HulldomainTessFactorPass.h
/// hulldomain's factor pre-pass: a compute dispatch that writes one level per
/// canonical control-mesh edge and per patch
/// (hulldomain_terrain_factors.comp), the D3D11 way of moving the metric out
/// of the hull shader so each shared edge is evaluated once.

#include "common/GpuTerrain.h"
#include "common/TerrainBindings.h"
#include "tessera/shaders/TessFactors.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <string>

namespace tessera::backends {

class HulldomainTessFactorPass {
public:
    HulldomainTessFactorPass() = default;
    HulldomainTessFactorPass(gpu::Device& device, const std::string& backendName);

    /// Records "terrain.factors": levels for every edge and patch of `terrain`
    /// into the slot's level buffers, then a barrier that makes them visible
    /// to the tessellation control stage.
    void record(gpu::FrameContext& frame, GpuTerrain& terrain, const gpu::UniformSlice& tessUniforms,
                const PushTerrainBindings& pushBindings);

private:
    gpu::PipelineLayout mLayout;
    gpu::ComputePipeline mPipeline;
};

} // namespace tessera::backends
