#include "StreamoutCrowdBinPass.h"

#include "StreamoutRecording.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"

#include "streamout_crowd_bin.geom.spv.h"
#include "streamout_crowd_bin.vert.spv.h"
#include "streamout_crowd_split.geom.spv.h"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace tessera::backends {
namespace {

constexpr VkDeviceSize kEntryBytes = sizeof(shader::CrowdListEntry);
constexpr VkDeviceSize kSurvivorBytes = StreamoutCrowdResources::kSurvivorBytes;

gpu::Pipeline survivorPipeline(gpu::Device& device, const gpu::PipelineLayout& layout, const char* name,
                               std::span<const uint32_t> geometry) {
    gpu::GraphicsPipelineDesc desc = streamout::streamOutPipelineDesc(
        name, layout, {{VK_SHADER_STAGE_VERTEX_BIT, streamout_crowd_bin_vert_spv}, {VK_SHADER_STAGE_GEOMETRY_BIT, geometry}});
    // A survivors' stream: (instance, next state) per point.
    desc.vertexBindings = {{0, uint32_t(kSurvivorBytes), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_UINT, 0}};
    return gpu::Pipeline(device, desc);
}

} // namespace

StreamoutCrowdBinPass::StreamoutCrowdBinPass(gpu::Device& device, const gpu::PipelineLayout& layout)
    : mLayout(&layout), mPipeline(survivorPipeline(device, layout, "streamout.crowd.bin", streamout_crowd_bin_geom_spv)),
      mSplitPipeline(survivorPipeline(device, layout, "streamout.crowd.split", streamout_crowd_split_geom_spv)) {}

void StreamoutCrowdBinPass::record(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                                   const StreamoutCrowdBindings& bindings) {
    gpu::PassScope pass(frame, "crowd.bin");
    VkCommandBuffer cmd = frame.cmd();
    split(frame, crowd, resources, bindings);
    const auto& fn = frame.device().fn();
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    const auto& ranges = crowd.creatureRanges(frame.slot());

    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    const VkBuffer lists = crowd.lists().handle();
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier) {
        bindings.push(frame, *mLayout, tier, 0, 0);
        // The mesh tiers read the split's short stream, the impostor tier
        // every survivor.
        const bool impostors = tier == TS_LOD_IMPOSTOR;
        const VkBuffer source = impostors ? resources.survivors().handle() : resources.meshSurvivors().handle();
        for (uint32_t c = 0; c < creatures; ++c) {
            // Every list gets its query, empty creatures too (their draw has
            // no vertices), so every result is available to copy.
            const VkDeviceSize from = ranges[c].y > 0 ? VkDeviceSize(ranges[c].x) * kSurvivorBytes : 0;
            vkCmdBindVertexBuffers(cmd, 0, 1, &source, &from);
            // The list's region holds the creature's instances (an empty
            // one an entry: lists() has one to spare at its end).
            const VkDeviceSize to = VkDeviceSize(crowd.listBase(frame.slot(), tier, c)) * kEntryBytes;
            const VkDeviceSize listBytes = VkDeviceSize(std::max(ranges[c].y, 1u)) * kEntryBytes;
            fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &lists, &to, &listBytes);
            const uint32_t query = resources.listQuery(tier, c);
            vkCmdBeginQuery(cmd, resources.queries(), query, 0);
            fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
            // A point per survivor (or mesh survivor), the count the cull
            // pass's (or the split's) query left in the command.
            const VkDeviceSize draw = impostors ? resources.binDraw(c) : resources.meshBinDraw(c);
            vkCmdDrawIndirect(cmd, resources.draws().handle(), draw, 1, 0);
            fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
            vkCmdEndQuery(cmd, resources.queries(), query);
        }
    }
    streamout::endStreamOut(cmd);

    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT,
                       VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                       VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT);
    copyCounts(cmd, crowd, resources);
}

void StreamoutCrowdBinPass::split(gpu::FrameContext& frame, GpuCrowd& crowd, StreamoutCrowdResources& resources,
                                  const StreamoutCrowdBindings& bindings) {
    VkCommandBuffer cmd = frame.cmd();
    const auto& fn = frame.device().fn();
    const auto& ranges = crowd.creatureRanges(frame.slot());
    const uint32_t creatures = uint32_t(ranges.size());
    streamout::beginStreamOut(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mSplitPipeline.handle());
    bindings.push(frame, *mLayout, 0, 0, 0);
    const VkBuffer survivors = resources.survivors().handle();
    const VkBuffer mesh = resources.meshSurvivors().handle();
    for (uint32_t c = 0; c < creatures; ++c) {
        // The creature's region in both streams (an empty creature's draw
        // has no vertices and writes nothing).
        const VkDeviceSize from = ranges[c].y > 0 ? VkDeviceSize(ranges[c].x) * kSurvivorBytes : 0;
        const VkDeviceSize bytes = VkDeviceSize(std::max(ranges[c].y, 1u)) * kSurvivorBytes;
        vkCmdBindVertexBuffers(cmd, 0, 1, &survivors, &from);
        fn.cmdBindTransformFeedbackBuffers(cmd, 0, 1, &mesh, &from, &bytes);
        vkCmdBeginQuery(cmd, resources.queries(), resources.meshSurvivorsQuery(c), 0);
        fn.cmdBeginTransformFeedback(cmd, 0, 0, nullptr, nullptr);
        vkCmdDrawIndirect(cmd, resources.draws().handle(), resources.binDraw(c), 1, 0);
        fn.cmdEndTransformFeedback(cmd, 0, 0, nullptr, nullptr);
        vkCmdEndQuery(cmd, resources.queries(), resources.meshSurvivorsQuery(c));
    }
    streamout::endStreamOut(cmd);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_ACCESS_2_TRANSFORM_FEEDBACK_WRITE_BIT_EXT, VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT,
                       VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT);
    // Each creature's mesh survivors count becomes the vertex count of its
    // mesh tiers' bin draws.
    resources.countsToDraws(cmd, resources.meshSurvivorsQuery(0), &StreamoutCrowdResources::meshBinDraw);
}

void StreamoutCrowdBinPass::copyCounts(VkCommandBuffer cmd, GpuCrowd& crowd, StreamoutCrowdResources& resources) {
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    resources.copyResults(cmd, resources.listQuery(0, 0), TS_LOD_TIERS * creatures);
    // Each list's count goes to its indexed draw's instance count; a near
    // list's also to the slots pass's vertex count and the skin pass's
    // instance count.
    constexpr VkDeviceSize kWord = sizeof(uint32_t);
    std::vector<VkBufferCopy> toArgs, toDraws;
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
        for (uint32_t c = 0; c < creatures; ++c) {
            const VkDeviceSize written = StreamoutCrowdResources::resultOffset(resources.listQuery(tier, c));
            const uint32_t list = tier * TS_CROWD_MAX_CHARACTERS + c;
            toArgs.push_back({written, (list * TS_CROWD_ARG_DRAW_WORDS + 1) * kWord, kWord});
            if (tier != TS_LOD_NEAR) continue;
            toDraws.push_back({written, resources.slotsDraw(c) + offsetof(VkDrawIndirectCommand, vertexCount), kWord});
            toDraws.push_back({written, resources.skinDraw(c) + offsetof(VkDrawIndirectCommand, instanceCount), kWord});
        }
    vkCmdCopyBuffer(cmd, resources.counts().handle(), crowd.args().handle(), uint32_t(toArgs.size()), toArgs.data());
    vkCmdCopyBuffer(cmd, resources.counts().handle(), resources.draws().handle(), uint32_t(toDraws.size()),
                    toDraws.data());
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT);
}

} // namespace tessera::backends
