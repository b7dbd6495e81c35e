#pragma once
/// @file HulldomainSubdivPass.h
/// hulldomain's Catmull-Clark surfaces (the second paper, D3D11 style): after
/// the shared compute refine (ComputeSubdivRefinePass), one patch per
/// tessellation domain, whose hull stage
/// sets the levels from its corners' per-vertex levels (or culls it) and
/// whose domain stage evaluates the shared subdiv_eval.glsl at
/// gl_TessCoord, levels up to 64.

#include "common/SubdivPipelines.h"
#include "common/GpuSubdiv.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class HulldomainSubdivPass {
public:
    HulldomainSubdivPass() = default;
    HulldomainSubdivPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat, bool wireframe);

    /// The stages of the draw that read the refined points.
    static constexpr VkPipelineStageFlags2 kPointReaders = VK_PIPELINE_STAGE_2_TESSELLATION_CONTROL_SHADER_BIT |
                                                           VK_PIPELINE_STAGE_2_TESSELLATION_EVALUATION_SHADER_BIT |
                                                           VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    /// "subdiv.draw", inside the main pass.
    void recordDraw(gpu::FrameContext& frame, GpuSubdiv& surface, const gpu::UniformSlice& frameUniforms,
                    const gpu::UniformSlice& uniforms, bool wireframe);

private:
    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    SubdivPipelines mPipelines;
};

} // namespace tessera::backends
