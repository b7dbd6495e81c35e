#include "HulldomainCrowdPass.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"

#include "character.frag_crowd.spv.h"
#include "crowd_mesh.vert.spv.h"
#include "hulldomain_character_patch.tesc_crowd.spv.h"
#include "hulldomain_character_patch.tese_crowd.spv.h"
#include "hulldomain_character_patch.vert_crowd.spv.h"
#include "hulldomain_crowd_cull.comp.spv.h"
#include "hulldomain_crowd_skin.comp.spv.h"

namespace tessera::backends {
namespace {

constexpr VkDeviceSize kWord = sizeof(uint32_t);

VkDeviceSize listArgsOffset(uint32_t tier, uint32_t creature) {
    return VkDeviceSize(tier * TS_CROWD_MAX_CHARACTERS + creature) * TS_CROWD_ARG_DRAW_WORDS * kWord;
}

} // namespace

HulldomainCrowdPass::HulldomainCrowdPass(gpu::Device& device, VkFormat colorFormat, VkFormat depthFormat)
    : mDevice(&device) {
    // One layout per bind point: lavapipe (Mesa 22.3) crashes in a later
    // pipeline-statistics query when compute pushes descriptors through a
    // layout whose bindings are also visible to graphics stages (fixed in
    // Mesa 25.0; kept for the machines that stay on 22.3).
    using Mode = CrowdDescriptors::Mode;
    mComputeLayout =
        CrowdDescriptors::layout(device, Mode::Storage, VK_SHADER_STAGE_COMPUTE_BIT, "hulldomain.crowd.computeLayout");
    mLayout = CrowdDescriptors::layout(device, Mode::Storage, VK_SHADER_STAGE_ALL_GRAPHICS, "hulldomain.crowd.layout");
    mCull = gpu::ComputePipeline(device, mComputeLayout, hulldomain_crowd_cull_comp_spv, "hulldomain.crowd.cull");
    mSkin = gpu::ComputePipeline(device, mComputeLayout, hulldomain_crowd_skin_comp_spv, "hulldomain.crowd.skin");

    gpu::GraphicsPipelineDesc desc;
    desc.layout = &mLayout;
    // Back faces culled. The tessellated near tier's triangles wind as the
    // domain's ccw ordering makes them, which the Y-flipped projection turns
    // clockwise (as the character passes); the middle and far tiers draw the
    // meshes' own glTF counter-clockwise triangles, which stay so.
    desc.cullMode = VK_CULL_MODE_BACK_BIT;
    desc.frontFace = VK_FRONT_FACE_CLOCKWISE;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    desc.name = "hulldomain.crowd.near";
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, hulldomain_character_patch_vert_crowd_spv},
                   {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, hulldomain_character_patch_tesc_crowd_spv},
                   {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, hulldomain_character_patch_tese_crowd_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, character_frag_crowd_spv}};
    desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    desc.patchControlPoints = 3;
    mNear = gpu::Pipeline(device, desc);
    mMesh = CrowdMeshPass(device, Mode::Storage, crowd_mesh_vert_spv, character_frag_crowd_spv, colorFormat, depthFormat,
                          "hulldomain.crowd.mesh");
}

void HulldomainCrowdPass::push(VkCommandBuffer cmd, VkPipelineBindPoint point,
                               std::span<const VkWriteDescriptorSet> writes) {
    const gpu::PipelineLayout& layout = point == VK_PIPELINE_BIND_POINT_COMPUTE ? mComputeLayout : mLayout;
    mDevice->fn().cmdPushDescriptorSet(cmd, point, layout.handle(), 0, uint32_t(writes.size()), writes.data());
}

void HulldomainCrowdPass::recordCompute(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                                        uint32_t instanceCount) {
    VkCommandBuffer cmd = frame.cmd();
    {
        gpu::PassScope pass(frame, "crowd.cull");
        // The previous frame's culling and draws are done with the state,
        // the lists and the commands before this one touches them.
        gpu::memoryBarrier(cmd,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT |
                               VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        if (!crowd.stateCleared()) {
            // Every id starts out of view: its first frame in view takes its
            // tier at once, without a fade.
            vkCmdFillBuffer(cmd, crowd.state().handle(), 0, VK_WHOLE_SIZE, shader::tsLodStateNone());
            crowd.setStateCleared();
        }
        const std::vector<uint32_t>& initial = crowd.initialArgs();
        vkCmdUpdateBuffer(cmd, crowd.args().handle(), 0, initial.size() * kWord, initial.data());
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mCull.handle());
        push(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, descriptors.writes(0));
        if (instanceCount > 0) vkCmdDispatch(cmd, (instanceCount + 63) / 64, 1, 1);
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                               VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                           VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                               VK_ACCESS_2_TRANSFER_READ_BIT);
    }
    {
        gpu::PassScope pass(frame, "crowd.skin");
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mSkin.handle());
        push(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, descriptors.writes(0));
        vkCmdDispatchIndirect(cmd, crowd.args().handle(), TS_CROWD_ARG_DISPATCH * kWord);
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    }
}

void HulldomainCrowdPass::recordDraws(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors) {
    VkCommandBuffer cmd = frame.cmd();
    {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mNear.handle());
        gpu::PassScope pass(frame, "crowd.near");
        vkCmdBindIndexBuffer(cmd, crowd.indices().handle(), 0, VK_INDEX_TYPE_UINT32);
        for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
            push(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, descriptors.writes(c));
            vkCmdDrawIndexedIndirect(cmd, crowd.args().handle(), listArgsOffset(TS_LOD_NEAR, c), 1, 0);
        }
    }
    mMesh.record(frame, crowd, descriptors);
}

} // namespace tessera::backends
