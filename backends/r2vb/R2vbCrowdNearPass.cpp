#include "R2vbCrowdNearPass.h"

#include "tessera/shaders/CharacterUniforms.h"
#include "common/CommandHelpers.h"
#include "R2vbRecording.h"

#include "r2vb_crowd_commands.vert.spv.h"
#include "r2vb_crowd_skin.vert.spv.h"
#include "r2vb_crowd_slots.frag.spv.h"
#include "r2vb_crowd_slots.vert.spv.h"
#include "r2vb_crowd_texel.frag.spv.h"

#include <cstddef>
#include <vector>

namespace tessera::backends {
namespace {

namespace crowd = r2vb::crowd;
constexpr VkFormat kUint4 = VK_FORMAT_R32G32B32A32_UINT;

glm::uvec4 sizeOf(const gpu::Image& image) {
    return {image.width(), image.height(), 0u, 0u};
}

/// Copies the first `texels` texels of `image`, just rendered, to `buffer`.
void copyOut(VkCommandBuffer cmd, const gpu::Image& image, uint64_t texels, const gpu::Buffer& buffer) {
    crowd::renderedToCopy(cmd, image);
    std::vector<VkBufferImageCopy> regions;
    crowd::appendCopy(regions, image, 0, texels, 0);
    crowd::copy(cmd, image, buffer, regions);
}

} // namespace

R2vbCrowdNearPass::R2vbCrowdNearPass(gpu::Device& device)
    : mDevice(&device), mLayout(crowd::layout(device, "r2vb.crowd.near.layout")),
      mSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "r2vb.crowd.near.sampler") {
    mSlots = gpu::Pipeline(device, r2vb::pointPipeline("r2vb.crowd.nearSlots", mLayout, r2vb_crowd_slots_vert_spv,
                                                       r2vb_crowd_slots_frag_spv, {kUint4, kUint4}));
    mCommands =
        gpu::Pipeline(device, r2vb::pointPipeline("r2vb.crowd.nearCommands", mLayout, r2vb_crowd_commands_vert_spv,
                                                  r2vb_crowd_texel_frag_spv, {kUint4}));
    gpu::GraphicsPipelineDesc skin = r2vb::pointPipeline("r2vb.crowd.nearSkin", mLayout, r2vb_crowd_skin_vert_spv,
                                                         r2vb_crowd_texel_frag_spv, {kUint4});
    // The crowd's bind-pose vertices (every creature's cage) as a stream;
    // each slot's draw starts at its creature's cage.
    GpuCharacter::useCageVertexStream(skin);
    mSkin = gpu::Pipeline(device, skin);
}

void R2vbCrowdNearPass::record(gpu::FrameContext& frame, crowd::FrameInputs& in) {
    VkCommandBuffer cmd = frame.cmd();
    {
        gpu::PassScope pass(frame, "crowd.nearSlots");
        writeSlots(cmd, in);
    }
    {
        gpu::PassScope pass(frame, "crowd.nearCommands");
        writeCommands(cmd, in);
    }
    gpu::PassScope pass(frame, "crowd.skin");
    skinCages(cmd, in);
}

void R2vbCrowdNearPass::writeSlots(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    GpuCrowd& c = *in.crowd;
    crowd::toTarget(cmd, t.slotRecords(), VK_PIPELINE_STAGE_2_COPY_BIT);
    crowd::toTarget(cmd, t.slotSkinDraws(), VK_PIPELINE_STAGE_2_COPY_BIT);
    gpu::Image* const targets[2] = {&t.slotRecords(), &t.slotSkinDraws()};
    crowd::beginWhole(cmd, targets);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mSlots.handle());
    const VkDescriptorImageInfo state{mSampler.handle(), t.state(t.stateRead()).view(),
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo even{mSampler.handle(), t.pyramid(0).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorImageInfo odd{mSampler.handle(), t.pyramid(1).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkWriteDescriptorSet writes[5] = {
        bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &in.uniforms),
        texelWrite(TS_BINDING_CROWD_INSTANCES, &in.instances), imageWrite(R2VB_CROWD_BINDING_STATE, &state),
        imageWrite(R2VB_CROWD_BINDING_EVEN, &even), imageWrite(R2VB_CROWD_BINDING_ODD, &odd)};
    in.constants.target = sizeOf(t.slotRecords());
    crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
    vkCmdDraw(cmd, c.nearSlots(), 1, 0, 0);
    vkCmdEndRendering(cmd);
    copyOut(cmd, t.slotRecords(), c.nearSlots(), c.nearSlotRecords());
    copyOut(cmd, t.slotSkinDraws(), c.nearSlots(), t.skinDrawBuffer());
    crowd::copiesToReaders(cmd);
}

void R2vbCrowdNearPass::writeCommands(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    GpuCrowd& c = *in.crowd;
    crowd::toTarget(cmd, t.nearCommands(), VK_PIPELINE_STAGE_2_COPY_BIT);
    gpu::Image* const targets[1] = {&t.nearCommands()};
    crowd::beginWhole(cmd, targets);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mCommands.handle());
    const VkBufferView slots = c.nearSlotsView();
    const VkWriteDescriptorSet writes[3] = {
        bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &in.uniforms),
        texelWrite(TS_BINDING_CROWD_INSTANCES, &in.instances), texelWrite(TS_BINDING_CROWD_SLOTS, &slots)};
    in.constants.target = sizeOf(t.nearCommands());
    crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
    // Two texels (eight words) per command.
    const uint32_t texels = uint32_t(c.creatures().size()) * c.nearSlots() * TS_CROWD_NEAR_COMMAND_WORDS / 4;
    vkCmdDraw(cmd, texels, 1, 0, 0);
    vkCmdEndRendering(cmd);
    copyOut(cmd, t.nearCommands(), texels, c.nearCommands());
    crowd::copiesToReaders(cmd);
}

void R2vbCrowdNearPass::skinCages(VkCommandBuffer cmd, crowd::FrameInputs& in) {
    R2vbCrowdTargets& t = *in.targets;
    GpuCrowd& c = *in.crowd;
    crowd::toTarget(cmd, t.nearCages(), VK_PIPELINE_STAGE_2_COPY_BIT);
    gpu::Image* const targets[1] = {&t.nearCages()};
    crowd::beginWhole(cmd, targets);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mSkin.handle());
    const VkBufferView baked = c.bakedView();
    const VkBufferView clips = c.clipsView();
    const VkBufferView slots = c.nearSlotsView();
    const VkWriteDescriptorSet writes[5] = {
        bufferWrite(TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, &in.uniforms),
        texelWrite(TS_BINDING_CROWD_INSTANCES, &in.instances), texelWrite(TS_BINDING_CROWD_BAKED, &baked),
        texelWrite(TS_BINDING_CROWD_CLIPS, &clips), texelWrite(TS_BINDING_CROWD_SLOTS, &slots)};
    in.constants.target = sizeOf(t.nearCages());
    crowd::push(*mDevice, cmd, mLayout, writes, in.constants);
    const VkBuffer stream = c.vertices().handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &stream, &offset);
    vkCmdDrawIndirect(cmd, t.skinDrawBuffer().handle(), 0, c.nearSlots(), sizeof(VkDrawIndirectCommand));
    vkCmdEndRendering(cmd);
    copyOut(cmd, t.nearCages(), uint64_t(c.nearSlots()) * c.nearStride(), c.nearCages());
    crowd::copiesToReaders(cmd);
}

} // namespace tessera::backends
