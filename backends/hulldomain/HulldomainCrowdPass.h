#pragma once
/// @file HulldomainCrowdPass.h
/// hulldomain's instanced crowd (D3D11 style, compute): the shared compute
/// passes (ComputeCrowdCullPass) cull the instances and bin them into the
/// tier lists, whose counts are the indirect draws' instance counts, and
/// skin the near tier's cages into compressed vertices; then per creature
/// an indirect tessellated draw (near), an indirect draw of the cage
/// (middle) and of the far mesh (far), skinned from the baked clips, and of
/// the card (impostor, CrowdImpostorPass). Cascaded shadows: the same draws
/// as casters, depth only, but the cards'.

#include "common/ComputeCrowdCullPass.h"
#include "common/CrowdDescriptors.h"
#include "common/CrowdImpostorPass.h"
#include "common/CrowdMeshPass.h"
#include "common/GpuCrowd.h"
#include "common/ShadowCasterPipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class HulldomainCrowdPass {
public:
    HulldomainCrowdPass() = default;
    HulldomainCrowdPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat);

    /// Outside the main pass: resets the indirect commands, culls and bins
    /// (GPU pass crowd.cull) and skins the near slots (crowd.skin); the
    /// commands' copy for the frame report is BasicCharacterBackend's.
    void recordCompute(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                       uint32_t instanceCount);
    /// Inside the main pass: each tier's draws (crowd.near, crowd.middle,
    /// crowd.far, crowd.impostor).
    void recordDraws(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors);
    /// Outside the main pass: every tier's draws as casters into the open
    /// shadow layer of the cascade `caster`.
    void recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                      const shader::ShadowCasterPush& caster);

private:
    /// The near tier's indirect tessellated draws, per creature its
    /// descriptors pushed through `layout`.
    void drawNear(VkCommandBuffer cmd, const gpu::PipelineLayout& layout, GpuCrowd& crowd,
                  CrowdDescriptors& descriptors);

    gpu::Device* mDevice = nullptr;
    ComputeCrowdCullPass mCull;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mNear;
    ShadowCasterPipeline mNearShadow;
    CrowdMeshPass mMesh;
    CrowdImpostorPass mImpostor;
};

} // namespace tessera::backends
