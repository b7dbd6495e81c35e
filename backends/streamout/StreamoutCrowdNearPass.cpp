#include "StreamoutCrowdNearPass.h"

#include "StreamoutRecording.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"

#include "streamout_crowd_commands.vert.spv.h"
#include "streamout_crowd_skin.vert.spv.h"
#include "streamout_crowd_slots.vert.spv.h"

namespace tessera::backends {
namespace {

constexpr uint32_t kEntryBytes = sizeof(shader::CrowdListEntry);

gpu::GraphicsPipelineDesc pointsDesc(const gpu::PipelineLayout& layout, const char* name,
                                     std::span<const uint32_t> vertex) {
    return streamout::streamOutPipelineDesc(name, layout, {{VK_SHADER_STAGE_VERTEX_BIT, vertex}});
}

} // namespace

StreamoutCrowdNearPass::StreamoutCrowdNearPass(gpu::Device& device, const gpu::PipelineLayout& layout)
    : mLayout(&layout) {
    // A near list's entries: per vertex for the slot records, per instance
    // for the skin pass.
    gpu::GraphicsPipelineDesc slots = pointsDesc(layout, "streamout.crowd.slots", streamout_crowd_slots_vert_spv);
    slots.vertexBindings = {{0, kEntryBytes, VK_VERTEX_INPUT_RATE_VERTEX}};
    slots.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32A32_UINT, 0}};
    mSlots = gpu::Pipeline(device, slots);
    mCommands =
        gpu::Pipeline(device, pointsDesc(layout, "streamout.crowd.commands", streamout_crowd_commands_vert_spv));
    gpu::GraphicsPipelineDesc skin = pointsDesc(layout, "streamout.crowd.skin", streamout_crowd_skin_vert_spv);
    skin.vertexBindings = {{0, kEntryBytes, VK_VERTEX_INPUT_RATE_INSTANCE}};
    skin.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32A32_UINT, 0}};
    mSkin = gpu::Pipeline(device, skin);
}

void StreamoutCrowdNearPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                                    const StreamoutCrowdBindings& bindings) {
    recordSlots(frame, crowd, resources, bindings);
    recordSkin(frame, crowd, resources, bindings);
}

void StreamoutCrowdNearPass::recordSlots(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                                         const StreamoutCrowdBindings& bindings) {
    gpu::PassScope pass(frame, "crowd.slots");
    VkCommandBuffer cmd = frame.cmd();
    const auto& fn = frame.device().fn();
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    const VkBuffer lists = crowd.lists().handle();
    const VkDeviceSize zero = 0;

    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mSlots.handle());
    bindings.push(frame, *mLayout, TS_LOD_NEAR, 0, 0);
    const VkBuffer records = crowd.nearSlotRecords().handle();
    const VkDeviceSize recordBytes = VkDeviceSize(crowd.nearSlots()) * sizeof(shader::CrowdNearSlot);
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &records, &zero, &recordBytes);
    // One transform-feedback session over every creature's draw: each draw
    // appends where the last one stopped.
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    for (uint32_t c = 0; c < creatures; ++c) {
        const VkDeviceSize list =
            VkDeviceSize(crowd.listBase(frame.slot(), TS_LOD_NEAR, c)) * kEntryBytes;
        vkCmdBindVertexBuffers(cmd, 0, 1, &lists, &list);
        vkCmdDrawIndirect(cmd, resources.draws().handle(), resources.slotsDraw(c), 1, 0);
    }
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                       VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);

    // The commands: vertex c * slots + s is command (c, s), 32 bytes each.
    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mCommands.handle());
    bindings.push(frame, *mLayout, TS_LOD_NEAR, 0, 0);
    const VkBuffer commands = crowd.nearCommands().handle();
    const VkDeviceSize commandBytes = crowd.nearCommands().size();
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &commands, &zero, &commandBytes);
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    vkCmdDraw(cmd, creatures * crowd.nearSlots(), 1, 0, 0);
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);
}

void StreamoutCrowdNearPass::recordSkin(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                                        const StreamoutCrowdBindings& bindings) {
    gpu::PassScope pass(frame, "crowd.skin");
    VkCommandBuffer cmd = frame.cmd();
    const auto& fn = frame.device().fn();
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    const VkBuffer lists = crowd.lists().handle();
    const VkDeviceSize zero = 0;

    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mSkin.handle());
    const VkBuffer cages = crowd.nearCages().handle();
    const VkDeviceSize cageBytes = crowd.nearCages().size();
    fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &cages, &zero, &cageBytes);
    fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    for (uint32_t c = 0; c < creatures; ++c) {
        bindings.push(frame, *mLayout, TS_LOD_NEAR, c, resources.cageBase(c));
        const VkDeviceSize list =
            VkDeviceSize(crowd.listBase(frame.slot(), TS_LOD_NEAR, c)) * kEntryBytes;
        vkCmdBindVertexBuffers(cmd, 0, 1, &lists, &list);
        vkCmdDrawIndirect(cmd, resources.draws().handle(), resources.skinDraw(c), 1, 0);
    }
    fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
    streamout::endStreamOut(cmd);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT,
                       VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
