#include "R2vbCrowdBinningPass.h"

#include "common/CommandHelpers.h"
#include "R2vbRecording.h"
#include "tessera/gpu/Barriers.h"

#include "fullscreen.vert.spv.h"
#include "r2vb_crowd_args.frag.spv.h"
#include "r2vb_crowd_args.vert.spv.h"
#include "r2vb_crowd_classify.vert.spv.h"
#include "r2vb_crowd_lists.vert.spv.h"
#include "r2vb_crowd_reduce.frag.spv.h"
#include "r2vb_crowd_state.frag.spv.h"
#include "r2vb_crowd_state.vert.spv.h"
#include "r2vb_crowd_texel.frag.spv.h"

#include <vector>

namespace tessera::backends {
namespace {

namespace crowd = r2vb::crowd;
constexpr VkFormat kUint4 = VK_FORMAT_R32G32B32A32_UINT;
constexpr VkPipelineStageFlags2 kShaders =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

glm::uvec4 sizeOf(const gpu::Image& image) {
    return {image.width(), image.height(), 0u, 0u};
}

} // namespace

R2vbCrowdBinningPass::R2vbCrowdBinningPass(gpu::Device& device)
    : mDevice(&device), mLayout(crowd::layout(device, "r2vb.crowd.binning.layout")),
      mSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "r2vb.crowd.binning.sampler") {
    mState = gpu::Pipeline(device, r2vb::pointPipeline("r2vb.crowd.state", mLayout, r2vb_crowd_state_vert_spv,
                                                       r2vb_crowd_state_frag_spv, {VK_FORMAT_R32_UINT}));
    mClassify = gpu::Pipeline(device, r2vb::pointPipeline("r2vb.crowd.classify", mLayout, r2vb_crowd_classify_vert_spv,
                                                          r2vb_crowd_texel_frag_spv, {kUint4}));
    gpu::GraphicsPipelineDesc reduce =
        r2vb::pointPipeline("r2vb.crowd.pyramid", mLayout, fullscreen_vert_spv, r2vb_crowd_reduce_frag_spv, {kUint4});
    reduce.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    mReduce = gpu::Pipeline(device, reduce);
    mArgs = gpu::Pipeline(device, r2vb::pointPipeline("r2vb.crowd.args", mLayout, r2vb_crowd_args_vert_spv,
                                                      r2vb_crowd_args_frag_spv, {kUint4, VK_FORMAT_R32_UINT}));
    mLists = gpu::Pipeline(device, r2vb::pointPipeline("r2vb.crowd.lists", mLayout, r2vb_crowd_lists_vert_spv,
                                                       r2vb_crowd_texel_frag_spv, {kUint4}));
}

VkDescriptorImageInfo R2vbCrowdBinningPass::sampled(const gpu::Image& image) const {
    return {mSampler.handle(), image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

void R2vbCrowdBinningPass::record(gpu::FrameContext& frame, crowd::FrameInputs& in) {
    VkCommandBuffer cmd = frame.cmd();
    // Every buffer these passes copy into was last read by an earlier
    // frame's draws, copies or readback; those reads end before any write.
    gpu::memoryBarrier(cmd,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT |
                           kShaders | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                       VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    {
        gpu::PassScope pass(frame, "crowd.state");
        updateState(cmd, in);
    }
    {
        gpu::PassScope pass(frame, "crowd.classify");
        classify(cmd, in);
    }
    {
        gpu::PassScope pass(frame, "crowd.pyramid");
        reduce(cmd, in);
    }
    {
        gpu::PassScope pass(frame, "crowd.args");
        writeArgs(cmd, in);
    }
    gpu::PassScope pass(frame, "crowd.lists");
    extractLists(cmd, in);
}

void R2vbCrowdBinningPass::updateState(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    VkClearColorValue none{};
    none.uint32[0] = shader::tsLodStateNone();
    gpu::Image& last = t.state(t.stateRead());
    gpu::Image& next = t.state(t.stateRead() ^ 1u);
    if (!t.stateCleared()) {
        // Every id starts out of view: its first frame in view takes its
        // tier at once, without a fade.
        crowd::toTarget(cmd, last, VK_PIPELINE_STAGE_2_NONE);
        gpu::Image* const first[1] = {&last};
        crowd::beginArea(cmd, first, {{0, 0}, {last.width(), last.height()}}, none);
        vkCmdEndRendering(cmd);
        crowd::renderedToSampled(cmd, last);
        t.setStateCleared();
    }
    // Cleared to "out of view": an id no instance lands on this frame.
    crowd::toTarget(cmd, next, kShaders);
    gpu::Image* const targets[1] = {&next};
    crowd::beginArea(cmd, targets, {{0, 0}, {next.width(), next.height()}}, none);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mState.handle());
    const VkDescriptorImageInfo state = sampled(last);
    const VkWriteDescriptorSet writes[4] = {
        bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &in.uniforms),
        texelWrite(TS_BINDING_CROWD_INSTANCES, &in.instances), imageWrite(R2VB_CROWD_BINDING_STATE, &state),
        texelWrite(TS_BINDING_CROWD_OCCLUDERS, &in.occluders)};
    in.constants.target = sizeOf(next);
    crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
    vkCmdDraw(cmd, in.instanceCount, 1, 0, 0);
    vkCmdEndRendering(cmd);
    crowd::renderedToSampled(cmd, next);
    t.flipState();
}

void R2vbCrowdBinningPass::classify(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    // Both atlases are rewritten; the last readers were an earlier frame's
    // traversals and reductions.
    crowd::toTarget(cmd, t.pyramid(0), kShaders);
    crowd::toTarget(cmd, t.pyramid(1), kShaders);
    gpu::Image* const targets[1] = {&t.pyramid(0)};
    const uint32_t side = t.pyramidSide();
    crowd::beginArea(cmd, targets, {{0, 0}, {side, side}}, {});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mClassify.handle());
    const VkDescriptorImageInfo state = sampled(t.state(t.stateRead()));
    const VkWriteDescriptorSet writes[3] = {
        bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &in.uniforms),
        texelWrite(TS_BINDING_CROWD_INSTANCES, &in.instances), imageWrite(R2VB_CROWD_BINDING_STATE, &state)};
    in.constants.target = glm::uvec4(side, side, 0u, 0u);
    crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
    vkCmdDraw(cmd, in.instanceCount, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

void R2vbCrowdBinningPass::reduce(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    const uint32_t side = t.pyramidSide();
    // Level l is written into atlas l % 2 while atlas (l - 1) % 2, holding
    // the level below, is sampled: no target is read while rendered into.
    bool isSampled[2] = {false, false};
    for (uint32_t level = 1; level <= t.pyramidTop(); ++level) {
        const uint32_t source = (level - 1) & 1u, dest = level & 1u;
        if (!isSampled[source]) crowd::renderedToSampled(cmd, t.pyramid(source));
        if (isSampled[dest]) crowd::sampledToTarget(cmd, t.pyramid(dest));
        isSampled[source] = true;
        isSampled[dest] = false;
        const shader::uvec2 origin = shader::r2vbPyramidOrigin(level, side);
        const uint32_t size = side >> level;
        gpu::Image* const targets[1] = {&t.pyramid(dest)};
        crowd::beginArea(cmd, targets, {{int32_t(origin.x), int32_t(origin.y)}, {size, size}}, {});
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mReduce.handle());
        const VkDescriptorImageInfo below = sampled(t.pyramid(source));
        const VkWriteDescriptorSet writes[1] = {imageWrite(R2VB_CROWD_BINDING_SOURCE, &below)};
        in.constants.target = glm::uvec4(size, size, level, 0u);
        crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
        vkCmdDraw(cmd, 3, 1, 0, 0);
        vkCmdEndRendering(cmd);
    }
    for (uint32_t parity = 0; parity < 2; ++parity)
        if (!isSampled[parity]) crowd::renderedToSampled(cmd, t.pyramid(parity));
}

void R2vbCrowdBinningPass::writeArgs(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    GpuCrowd& c = *in.crowd;
    crowd::toTarget(cmd, t.listDraws(), VK_PIPELINE_STAGE_2_COPY_BIT);
    crowd::toTarget(cmd, t.listCounts(), VK_PIPELINE_STAGE_2_COPY_BIT);
    gpu::Image* const targets[2] = {&t.listDraws(), &t.listCounts()};
    crowd::beginWhole(cmd, targets);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mArgs.handle());
    const VkDescriptorImageInfo even = sampled(t.pyramid(0));
    const VkDescriptorImageInfo odd = sampled(t.pyramid(1));
    const VkWriteDescriptorSet writes[3] = {
        bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &in.uniforms),
        imageWrite(R2VB_CROWD_BINDING_EVEN, &even), imageWrite(R2VB_CROWD_BINDING_ODD, &odd)};
    in.constants.target = sizeOf(t.listDraws());
    crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
    vkCmdDraw(cmd, t.listCount(), 1, 0, 0);
    vkCmdEndRendering(cmd);
    crowd::renderedToCopy(cmd, t.listDraws());
    crowd::renderedToCopy(cmd, t.listCounts());

    // Every word but the counts as the frame starts them, then each list's
    // count over its draw's instance count (word 1).
    const std::vector<uint32_t>& initial = c.initialArgs(in.slot);
    vkCmdUpdateBuffer(cmd, c.args().handle(), 0, initial.size() * sizeof(uint32_t), initial.data());
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    const uint32_t creatures = uint32_t(c.creatures().size());
    std::vector<VkBufferImageCopy> counts;
    for (uint32_t u = 0; u < t.listCount(); ++u) {
        const uint32_t list = (u / creatures) * TS_CROWD_MAX_CHARACTERS + u % creatures;
        VkBufferImageCopy region{};
        region.bufferOffset = VkDeviceSize(list * TS_CROWD_ARG_DRAW_WORDS + 1) * sizeof(uint32_t);
        region.imageSubresource = {t.listCounts().aspect(), 0, 0, 1};
        region.imageOffset = {int32_t(u), 0, 0};
        region.imageExtent = {1, 1, 1};
        counts.push_back(region);
    }
    crowd::copy(cmd, t.listCounts(), c.args(), counts);
    std::vector<VkBufferImageCopy> draws;
    crowd::appendCopy(draws, t.listDraws(), 0, t.listCount(), 0);
    crowd::copy(cmd, t.listDraws(), t.listDrawBuffer(), draws);
    crowd::copiesToReaders(cmd);
}

void R2vbCrowdBinningPass::extractLists(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    GpuCrowd& c = *in.crowd;
    gpu::Image& entries = t.entries();
    crowd::toTarget(cmd, entries, VK_PIPELINE_STAGE_2_COPY_BIT);
    gpu::Image* const targets[1] = {&entries};
    crowd::beginWhole(cmd, targets);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLists.handle());
    const VkDescriptorImageInfo state = sampled(t.state(t.stateRead()));
    const VkDescriptorImageInfo even = sampled(t.pyramid(0));
    const VkDescriptorImageInfo odd = sampled(t.pyramid(1));
    const VkWriteDescriptorSet writes[5] = {
        bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &in.uniforms),
        texelWrite(TS_BINDING_CROWD_INSTANCES, &in.instances), imageWrite(R2VB_CROWD_BINDING_STATE, &state),
        imageWrite(R2VB_CROWD_BINDING_EVEN, &even), imageWrite(R2VB_CROWD_BINDING_ODD, &odd)};
    in.constants.target = sizeOf(entries);
    crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
    vkCmdDrawIndirect(cmd, t.listDrawBuffer().handle(), 0, t.listCount(), sizeof(VkDrawIndirectCommand));
    vkCmdEndRendering(cmd);
    crowd::renderedToCopy(cmd, entries);

    // Each list's region, as many entries as its creature has instances
    // (the most it can hold), to its own region of crowd.lists(): the R2VB
    // step that makes them an instance stream.
    const uint32_t creatures = uint32_t(c.creatures().size());
    const uint32_t regionRows = t.listRegionTexels() / entries.width();
    const auto& ranges = c.creatureRanges(in.slot);
    std::vector<VkBufferImageCopy> regions;
    for (uint32_t u = 0; u < t.listCount(); ++u) {
        const uint32_t tier = u / creatures, creature = u % creatures;
        if (ranges[creature].y == 0) continue;
        crowd::appendCopy(regions, entries, u * regionRows, ranges[creature].y,
                          VkDeviceSize(c.listBase(in.slot, tier, creature)) * sizeof(shader::CrowdListEntry));
    }
    crowd::copy(cmd, entries, c.lists(), regions);
    crowd::copiesToReaders(cmd);
}

} // namespace tessera::backends
