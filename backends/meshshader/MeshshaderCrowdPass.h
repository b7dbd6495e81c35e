#pragma once
/// @file MeshshaderCrowdPass.h
/// meshshader's instanced crowd: the shared compute passes
/// (ComputeCrowdCullPass) cull the instances into the tier lists and skin
/// the near slots' cages; inside crowd.cull a one-workgroup compute pass
/// turns the lists' counts into task-shader commands
/// (meshshader_crowd_args.comp). Then per tier and creature an indirect
/// mesh-task draw: the near tier through the character task and mesh
/// shaders in their crowd variant (each instance tessellated at its own
/// level, as hulldomain's hull stage selects it), the middle and far tiers
/// as meshlets culled per instance in the task stage, the impostor tier as
/// cards from a mesh stage alone (MeshshaderCrowdImpostorPass).

#include "common/ComputeCrowdCullPass.h"
#include "common/CrowdDescriptors.h"
#include "common/GpuCrowd.h"
#include "MeshshaderCrowdImpostorPass.h"
#include "MeshshaderCrowdResources.h"
#include "common/ShadowCasterPipeline.h"
#include "MeshshaderPatternTables.h"
#include "tessera/gpu/ComputePipeline.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

namespace tessera::backends {

class MeshshaderCrowdPass {
public:
    MeshshaderCrowdPass() = default;
    MeshshaderCrowdPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat);

    /// Outside the main pass: culls and bins (crowd.cull, the task commands
    /// included) and skins the near slots (crowd.skin).
    void recordCompute(gpu::FrameContext& frame, GpuCrowd& crowd, MeshshaderCrowdResources& resources,
                       CrowdDescriptors& descriptors, uint32_t instanceCount);
    /// Inside the main pass: each tier's draws (crowd.near, crowd.middle,
    /// crowd.far, crowd.impostor).
    void recordDraws(gpu::FrameContext& frame, GpuCrowd& crowd, MeshshaderCrowdResources& resources,
                     CrowdDescriptors& descriptors);
    /// Outside the main pass: every tier's draws as casters into the open
    /// shadow layer of the cascade `caster` (the mesh stages' caster
    /// variants; the meshlets' task stage without its camera culling).
    void recordShadow(gpu::FrameContext& frame, GpuCrowd& crowd, MeshshaderCrowdResources& resources,
                      CrowdDescriptors& descriptors, const shader::ShadowCasterPush& caster);

    /// Bytes of the near tier's pattern tables.
    uint64_t tableBytes() const { return mTables.bytes(); }

private:
    void recordCommands(VkCommandBuffer cmd, GpuCrowd& crowd, MeshshaderCrowdResources& resources);
    /// One tier's indirect task draws, per creature its descriptors pushed
    /// through `layout` and its list's push constants for `pushStages`;
    /// `casters` (the middle and far tiers): the far mesh's simplified
    /// shadow casters' meshlets.
    void drawTier(VkCommandBuffer cmd, const gpu::PipelineLayout& layout, VkShaderStageFlags pushStages,
                  uint32_t tier, GpuCrowd& crowd, MeshshaderCrowdResources& resources, CrowdDescriptors& descriptors,
                  bool casters);

    gpu::Device* mDevice = nullptr;
    ComputeCrowdCullPass mCull;
    gpu::PipelineLayout mArgsLayout;
    gpu::ComputePipeline mArgs;
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mNear;
    gpu::Pipeline mMeshlets;
    ShadowCasterPipeline mNearShadow;
    ShadowCasterPipeline mMeshletsShadow;
    MeshshaderPatternTables mTables;
    MeshshaderCrowdImpostorPass mImpostor;
};

} // namespace tessera::backends
