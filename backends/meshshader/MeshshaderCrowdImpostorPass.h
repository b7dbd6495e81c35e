#pragma once
/// @file MeshshaderCrowdImpostorPass.h
/// meshshader's impostor tier: per creature one indirect mesh-task draw of
/// its impostor list with no task stage, a mesh workgroup per
/// TS_CROWD_IMPOSTOR_CARDS entries emitting their cards
/// (meshshader_crowd_impostor.mesh, the corners of crowd_impostor.glsl),
/// shaded by the fragment shader every backend's cards share
/// (crowd_impostor.frag). The commands are written with the other tiers'
/// in crowd.cull (meshshader_crowd_args.comp, tsCrowdImpostorCommand). The
/// cards cast no cascaded shadow (CrowdImpostorPass.h says why).

#include "common/CrowdDescriptors.h"
#include "common/GpuCrowd.h"
#include "MeshshaderCrowdResources.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class MeshshaderCrowdImpostorPass {
public:
    MeshshaderCrowdImpostorPass() = default;
    MeshshaderCrowdImpostorPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat);

    /// Inside the main pass, after the far tier: GPU pass crowd.impostor.
    void record(gpu::FrameContext& frame, GpuCrowd& crowd, MeshshaderCrowdResources& resources,
                CrowdDescriptors& descriptors);

private:
    gpu::Device* mDevice = nullptr;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mPipeline;
};

} // namespace tessera::backends
