#include "common/ComputeSubdivRefinePass.h"

#include "common/CommandHelpers.h"
#include "tessera/gpu/Barriers.h"

#include "subdiv_refine.comp.spv.h"

namespace tessera::backends {

ComputeSubdivRefinePass::ComputeSubdivRefinePass(gpu::Device& device, const std::string& backendName)
    : mDevice(&device) {
    const VkShaderStageFlags compute = VK_SHADER_STAGE_COMPUTE_BIT;
    std::vector<gpu::BindingDesc> refine = GpuSubdiv::refineBindings(compute);
    refine.push_back({TS_BINDING_SUBDIV_POINTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, compute});
    mLayout = gpu::PipelineLayout(device, refine, sizeof(uint32_t), compute, backendName + ".subdivRefine.layout");
    mPipeline = gpu::ComputePipeline(device, mLayout, subdiv_refine_comp_spv, backendName + ".subdivRefine");
}

void ComputeSubdivRefinePass::record(gpu::FrameContext& frame, GpuSubdiv& surface, VkPipelineStageFlags2 readers) {
    VkCommandBuffer cmd = frame.cmd();
    gpu::PassScope pass(frame, "subdiv.refine");
    // The previous frame's draw may still read the points (write after read).
    gpu::memoryBarrier(cmd, readers, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                       VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline.handle());
    const VkDescriptorBufferInfo points{surface.points().handle(), 0, VK_WHOLE_SIZE};
    std::vector<VkWriteDescriptorSet> writes = surface.refineWrites(frame.slot());
    writes.push_back(bufferWrite(TS_BINDING_SUBDIV_POINTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, &points));
    mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mLayout.handle(), 0,
                                       uint32_t(writes.size()), writes.data());
    const uint32_t count = surface.refinedPointCount();
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof count, &count);
    vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, readers,
                       VK_ACCESS_2_SHADER_READ_BIT);
}

} // namespace tessera::backends
