#pragma once
/// @file MeshshaderSubdivPass.h
/// meshshader's Catmull-Clark surfaces (the second paper through task and
/// mesh shaders): after the shared compute refine, a task stage takes each
/// domain's levels from its corners' per-vertex levels (or culls it) and
/// launches one mesh workgroup per piece of its pattern; the mesh stage
/// evaluates the shared subdiv_eval.glsl at the pattern's points, levels up
/// to 64 (meshshader_subdiv.task/.mesh).

#include "common/SubdivPipelines.h"
#include "common/GpuSubdiv.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/PipelineLayout.h"
#include "MeshshaderPatternTables.h"

namespace tessera::backends {

class MeshshaderSubdivPass {
public:
    MeshshaderSubdivPass() = default;
    MeshshaderSubdivPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat, bool wireframe);

    /// The stages of the draw that read the refined points.
    static constexpr VkPipelineStageFlags2 kPointReaders = VK_PIPELINE_STAGE_2_TASK_SHADER_BIT_EXT |
                                                           VK_PIPELINE_STAGE_2_MESH_SHADER_BIT_EXT |
                                                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

    /// "subdiv.draw", inside the main pass.
    void recordDraw(gpu::FrameContext& frame, GpuSubdiv& surface, const gpu::UniformSlice& frameUniforms,
                    const gpu::UniformSlice& uniforms, bool wireframe);

private:
    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    SubdivPipelines mPipelines;
    MeshshaderPatternTables mTables;
};

} // namespace tessera::backends
