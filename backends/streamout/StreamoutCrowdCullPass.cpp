#include "StreamoutCrowdCullPass.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"

#include "streamout_crowd_cull.geom.spv.h"
#include "streamout_crowd_cull.vert.spv.h"
#include "streamout_crowd_state.frag.spv.h"

#include <cstddef>
#include <vector>

namespace tessera::backends {
namespace {

constexpr VkDeviceSize kRecordBytes = StreamoutCrowdResources::kSurvivorBytes;

} // namespace

StreamoutCrowdCullPass::StreamoutCrowdCullPass(gpu::Device& device, const gpu::PipelineLayout& layout)
    : mLayout(&layout) {
    gpu::GraphicsPipelineDesc desc;
    desc.name = "streamout.crowd.cull";
    desc.layout = &layout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, streamout_crowd_cull_vert_spv},
                   {VK_SHADER_STAGE_GEOMETRY_BIT, streamout_crowd_cull_geom_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, streamout_crowd_state_frag_spv}};
    // No vertex buffer: the vertex index is the instance (texel fetches).
    desc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = false;
    desc.depthWrite = false;
    // Rasterised, unlike the other stream-out passes: the survivors' points
    // write the state target while transform feedback captures them.
    desc.colorFormats = {VK_FORMAT_R32_UINT};
    mPipeline = gpu::Pipeline(device, desc);
}

void StreamoutCrowdCullPass::reset(VkCommandBuffer cmd, GpuCrowd& crowd, StreamoutCrowdResources& resources) {
    // The previous frame's (or draw's) passes and draws are done with the
    // commands, queries, lists and near slots before this one rewrites them.
    gpu::memoryBarrier(cmd,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT |
                           VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT);
    // Every list starts empty (its mesh's command, no instances); a slot no
    // near entry takes stays unused (flags 0).
    const std::vector<uint32_t>& initial = crowd.initialArgs(crowd.lastSlot()); // this frame's, uploaded last
    vkCmdUpdateBuffer(cmd, crowd.args().handle(), 0, initial.size() * sizeof(uint32_t), initial.data());
    vkCmdFillBuffer(cmd, crowd.nearSlotRecords().handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdResetQueryPool(cmd, resources.queries(), 0, resources.queryCount());
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT |
                           VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                       VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT |
                           VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

void StreamoutCrowdCullPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                                    const StreamoutCrowdBindings& bindings) {
    gpu::PassScope pass(frame, "crowd.cull");
    VkCommandBuffer cmd = frame.cmd();
    const auto& fn = frame.device().fn();
    reset(cmd, crowd, resources);
    gpu::Image& target = resources.stateWrite();
    // Last frame's cull pass loaded this target; it is cleared, so its
    // contents need not survive the transition.
    gpu::transitionImage(cmd, target.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, 0,
                         VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);

    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color.uint32[0] = shader::tsLodStateNone();
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {target.width(), target.height()}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &rendering);
    const VkViewport viewport{0.0f, 0.0f, float(target.width()), float(target.height()), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    bindings.push(frame, *mLayout, 0, 0, 0);

    const VkBuffer survivors = resources.survivors().handle();
    const auto& ranges = crowd.creatureRanges(frame.slot());
    for (uint32_t c = 0; c < ranges.size(); ++c) {
        // Every creature's query runs, an empty one's too (it counts 0), so
        // every result is available to copy.
        vkCmdBeginQuery(cmd, resources.queries(), resources.survivorsQuery(c), 0);
        if (ranges[c].y > 0) {
            const VkDeviceSize offset = VkDeviceSize(ranges[c].x) * kRecordBytes;
            const VkDeviceSize size = VkDeviceSize(ranges[c].y) * kRecordBytes;
            fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &survivors, &offset, &size);
            fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
            vkCmdDraw(cmd, ranges[c].y, 1, ranges[c].x, 0);
            fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
        }
        vkCmdEndQuery(cmd, resources.queries(), resources.survivorsQuery(c));
    }
    vkCmdEndRendering(cmd);

    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                       VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
    gpu::transitionImage(cmd, target.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);

    // Each creature's survivors count becomes the vertex count of its bin
    // draws (what draw-auto would read from a counter; see
    // StreamoutCrowdResources.h for why a query feeds it instead).
    resources.countsToDraws(cmd, resources.survivorsQuery(0), &StreamoutCrowdResources::binDraw);
    resources.flipState();
}

} // namespace tessera::backends
