#pragma once
/// @file MeshshaderTerrainPass.h
/// meshshader's tessellated terrain: a task stage that reads each visible
/// patch's levels, culls it and launches one mesh workgroup per piece of its
/// pattern, and a mesh stage that places and displaces the piece's points
/// (meshshader_terrain.task/.mesh). Owns the pattern tables
/// (tessellator::MeshPatternLibrary), uploaded once.

#include "common/FillWirePipelines.h"
#include "common/GpuTerrain.h"
#include "common/TerrainBindings.h"
#include "MeshshaderPatternTables.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"

#include <span>

namespace tessera::backends {

class MeshshaderTerrainPass {
public:
    MeshshaderTerrainPass() = default;
    MeshshaderTerrainPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat, bool wireframe);

    /// Records the draw of `visiblePatches` (their levels already in the
    /// slot's level buffers in adaptive mode) into the open main pass.
    void record(gpu::FrameContext& frame, GpuTerrain& terrain, std::span<const uint32_t> visiblePatches,
                const gpu::UniformSlice& tessUniforms, const PushTerrainBindings& pushBindings, bool wireframe);

    /// Bytes of the pattern tables.
    uint64_t tableBytes() const { return mTables.bytes(); }

private:
    gpu::PipelineLayout mLayout;
    FillWirePipelines mPipelines;
    MeshshaderPatternTables mTables;
};

} // namespace tessera::backends
