#include "StreamoutSubdivRefinePass.h"

#include "common/CommandHelpers.h"
#include "StreamoutRecording.h"
#include "tessera/gpu/Barriers.h"

#include "streamout_subdiv_refine.vert.spv.h"

namespace tessera::backends {

namespace {
// Every stage that reads refined points: the factor pass, the emulated
// draw's evaluation and its fragment shading.
constexpr VkPipelineStageFlags2 kPointReads =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
} // namespace

StreamoutSubdivRefinePass::StreamoutSubdivRefinePass(gpu::Device& device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = gpu::PipelineLayout(device, GpuSubdiv::refineBindings(vertex), 0, 0, "streamout.subdivRefine.layout");
    gpu::GraphicsPipelineDesc desc = streamout::streamOutPipelineDesc(
        "streamout.subdivRefine", mLayout, {{VK_SHADER_STAGE_VERTEX_BIT, streamout_subdiv_refine_vert_spv}});
    // No vertex stream: the vertex index is the refined point.
    mPipeline = gpu::Pipeline(device, desc);
}

void StreamoutSubdivRefinePass::record(gpu::FrameContext& frame, GpuSubdiv& surface) {
    gpu::PassScope pass(frame, "subdiv.refine");
    VkCommandBuffer cmd = frame.cmd();
    const auto& fn = frame.device().fn();
    // The previous draw of this surface may still read the points (write
    // after read: an execution dependency is enough).
    gpu::memoryBarrier(cmd, kPointReads, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT);
    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const std::vector<VkWriteDescriptorSet> writes = surface.refineWrites(frame.slot());
    fn.cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0, uint32_t(writes.size()),
                            writes.data());
    const VkBuffer points = surface.points().handle();
    const VkDeviceSize zero = 0;
    const VkDeviceSize size = surface.points().size();
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &points, &zero, &size);
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    vkCmdDraw(cmd, surface.refinedPointCount(), 1, 0, 0);
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT, VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT,
                       kPointReads, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
