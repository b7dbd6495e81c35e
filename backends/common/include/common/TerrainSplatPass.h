#pragma once
/// @file TerrainSplatPass.h
/// Stamps craters into a terrain's GPU height map by rendering into it (the
/// first paper's "render (splat) the crater height fields into the dynamic
/// height texture"). Only render targets and copies, so every backend,
/// D3D9-style included, uses it.

#include "common/GpuTerrain.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/Sampler.h"
#include "tessera/terrain/CraterSplat.h"

#include <span>
#include <string>

namespace tessera::backends {

class TerrainSplatPass {
public:
    TerrainSplatPass() = default;
    TerrainSplatPass(gpu::Device& device, const std::string& backendName);

    /// Records one "terrain.splat" pass applying `splats` in order. Must run
    /// outside any rendering; leaves the height map SHADER_READ_ONLY_OPTIMAL
    /// and visible to every later shader stage.
    void record(gpu::FrameContext& frame, GpuTerrain& terrain, std::span<const terrain::CraterSplat> splats);

private:
    void splatOne(VkCommandBuffer cmd, GpuTerrain& terrain, const terrain::CraterSplat& splat);

    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
    gpu::Sampler mNearest; ///< integer texels are fetched, never filtered
};

} // namespace tessera::backends
