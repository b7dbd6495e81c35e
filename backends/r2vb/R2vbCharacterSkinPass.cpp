#include "R2vbCharacterSkinPass.h"

#include "tessera/shaders/FrameUniforms.h"
#include "R2vbRecording.h"
#include "shaders/R2vbLayout.h"
#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/FrameContext.h"

#include "r2vb_character_skin.frag.spv.h"
#include "r2vb_character_skin.vert.spv.h"

namespace tessera::backends {
namespace {

// Rows of R2VB_CAGE_WIDTH texels; GpuCharacter sizes compressed buffers in
// whole rows of the same width, so a copy of `rows` rows always fits.
uint32_t rowsFor(uint32_t vertices) { return (vertices + R2VB_CAGE_WIDTH - 1) / R2VB_CAGE_WIDTH; }

} // namespace

R2vbCharacterSkinPass::R2vbCharacterSkinPass(gpu::Device& device) : mDevice(&device) {
    const VkShaderStageFlags vertex = VK_SHADER_STAGE_VERTEX_BIT;
    mLayout = characterLayout(device, CharacterBindings::Skin, vertex, VK_DESCRIPTOR_TYPE_MAX_ENUM,
                              sizeof(shader::R2vbTargetConstants), vertex, "r2vb.characterSkin.layout");
    gpu::GraphicsPipelineDesc desc =
        r2vb::pointPipeline("r2vb.characterSkin", mLayout, r2vb_character_skin_vert_spv,
                            r2vb_character_skin_frag_spv, {VK_FORMAT_R32G32B32A32_UINT});
    GpuCharacter::useCageVertexStream(desc);
    mPipeline = gpu::Pipeline(device, desc);
}

uint64_t R2vbCharacterSkinPass::bytes() const {
    return mTarget.valid() ? uint64_t(mTarget.width()) * mTarget.height() * 16 : 0;
}

gpu::Image& R2vbCharacterSkinPass::targetFor(uint32_t vertices) {
    const uint32_t rows = rowsFor(vertices);
    if (mTarget.valid() && mTarget.height() >= rows) return mTarget;
    // A frame in flight may still copy from the old target.
    if (mTarget.valid()) mTarget.deferredReset();
    gpu::ImageDesc desc;
    desc.width = R2VB_CAGE_WIDTH;
    desc.height = rows;
    desc.format = VK_FORMAT_R32G32B32A32_UINT;
    desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    desc.name = "r2vb.characterSkin.target";
    mTarget = gpu::Image(*mDevice, desc);
    return mTarget;
}

void R2vbCharacterSkinPass::record(gpu::FrameContext& frame, const CharacterInstance& instance,
                                   const CharacterPushFn& push) {
    VkCommandBuffer cmd = frame.cmd();
    GpuCharacter& c = *instance.character;
    gpu::Image& target = targetFor(c.vertexCount());
    const uint32_t rows = rowsFor(c.vertexCount());
    // The previous instance's copy (or an earlier frame's) read this target last.
    const VkImageMemoryBarrier2 toTarget =
        gpu::imageBarrier(target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                           VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    gpu::pipelineBarrier(cmd, {&toTarget, 1});
    gpu::Image* const attachments[1] = {&target};
    r2vb::beginPoints(cmd, attachments, rows, mLayout);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    push(VK_PIPELINE_BIND_POINT_GRAPHICS, CharacterBindings::Skin, mLayout, instance, {});
    const VkBuffer stream = c.vertices().handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &stream, &offset);
    vkCmdDraw(cmd, c.vertexCount(), 1, 0, 0);
    vkCmdEndRendering(cmd);

    // The R2VB step: the target's rows become the instance's vertex data.
    const VkImageMemoryBarrier2 toCopy =
        gpu::imageBarrier(target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    gpu::pipelineBarrier(cmd, {&toCopy, 1});
    r2vb::copyRows(cmd, target, rows, instance.compressed->buffer, 0);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
