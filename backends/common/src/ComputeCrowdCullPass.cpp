#include "common/ComputeCrowdCullPass.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"

#include "crowd_cull.comp.spv.h"
#include "crowd_skin.comp.spv.h"

namespace tessera::backends {
namespace {

constexpr VkDeviceSize kWord = sizeof(uint32_t);

} // namespace

ComputeCrowdCullPass::ComputeCrowdCullPass(gpu::Device& device, const std::string& backendName) : mDevice(&device) {
    // A layout of its own, compute only: lavapipe (Mesa 22.3) crashes in a
    // later pipeline-statistics query when compute pushes descriptors
    // through a layout whose bindings are also visible to graphics stages
    // (fixed in Mesa 25.0; kept for the machines that stay on 22.3).
    mLayout = CrowdDescriptors::layout(device, CrowdDescriptors::Mode::Storage, VK_SHADER_STAGE_COMPUTE_BIT,
                                       backendName + ".crowd.computeLayout");
    mCull = gpu::ComputePipeline(device, mLayout, crowd_cull_comp_spv, backendName + ".crowd.cull");
    mSkin = gpu::ComputePipeline(device, mLayout, crowd_skin_comp_spv, backendName + ".crowd.skin");
}

void ComputeCrowdCullPass::push(VkCommandBuffer cmd, CrowdDescriptors& descriptors) {
    const auto writes = descriptors.writes(0);
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mLayout.handle(), 0,
                                       uint32_t(writes.size()), writes.data());
}

void ComputeCrowdCullPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, CrowdDescriptors& descriptors,
                                  uint32_t instanceCount, VkPipelineStageFlags2 nearReader,
                                  const std::function<void(VkCommandBuffer)>& binned) {
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
        const std::vector<uint32_t>& initial = crowd.initialArgs(frame.slot());
        vkCmdUpdateBuffer(cmd, crowd.args().handle(), 0, initial.size() * kWord, initial.data());
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mCull.handle());
        push(cmd, descriptors);
        if (instanceCount > 0) vkCmdDispatch(cmd, (instanceCount + 63) / 64, 1, 1);
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                               VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                           VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                               VK_ACCESS_2_TRANSFER_READ_BIT);
        if (binned) binned(cmd);
    }
    {
        gpu::PassScope pass(frame, "crowd.skin");
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mSkin.handle());
        // Pushed again: a technique's work in `binned` may have bound
        // another compute layout.
        push(cmd, descriptors);
        vkCmdDispatchIndirect(cmd, crowd.args().handle(), TS_CROWD_ARG_DISPATCH * kWord);
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                           nearReader, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    }
}

} // namespace tessera::backends
