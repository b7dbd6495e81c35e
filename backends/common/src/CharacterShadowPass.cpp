#include "common/CharacterShadowPass.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/shaders/CharacterShadow.h"

#include "character_shadow.frag.spv.h"
#include "character_shadow.vert.spv.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace tessera::backends {
namespace {
/// A shadow never runs longer than this many heights (a sun near the horizon).
constexpr float kMaxShadowLength = 4.0f;
} // namespace

CharacterShadowPass::CharacterShadowPass(gpu::Device& device, const std::string& backendName) : mDevice(&device) {
    mLayout = gpu::PipelineLayout(device, std::span<const gpu::BindingDesc>{}, sizeof(shader::CharacterShadowParams),
                                  VK_SHADER_STAGE_VERTEX_BIT,
                                  backendName + ".characterShadow.layout");
    gpu::GraphicsPipelineDesc desc;
    desc.name = backendName + ".characterShadow";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, character_shadow_vert_spv},
                   {VK_SHADER_STAGE_FRAGMENT_BIT, character_shadow_frag_spv}};
    // One caster per instance, as the D3D9 era instanced from a second stream.
    desc.vertexBindings = {{0, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_INSTANCE}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = false;
    desc.depthWrite = false;
    desc.alphaBlend = true;
    desc.colorFormats = {VK_FORMAT_R8_UNORM};
    mPipeline = gpu::Pipeline(device, desc);

    gpu::ImageDesc mask;
    mask.width = TS_CHARACTER_SHADOW_SIZE;
    mask.height = TS_CHARACTER_SHADOW_SIZE;
    mask.format = VK_FORMAT_R8_UNORM;
    mask.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    mask.name = backendName + ".characterShadow.mask";
    mMask = gpu::Image(device, mask);
    // Starts empty and readable, so a frame without casters can bind it.
    const std::vector<std::byte> empty(size_t(TS_CHARACTER_SHADOW_SIZE) * TS_CHARACTER_SHADOW_SIZE, std::byte{0});
    mMask.upload(empty, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    mSampler = gpu::Sampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                            backendName + ".characterShadow.sampler");
}

VkDescriptorImageInfo CharacterShadowPass::descriptor() const {
    return {mSampler.handle(), mMask.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

void CharacterShadowPass::record(gpu::FrameContext& frame, std::span<const glm::vec4> casters,
                                 const glm::vec3& region, const glm::vec3& sun) {
    if (!valid() || casters.empty() || region.z <= 0.0f) return;
    const size_t count = std::min<size_t>(casters.size(), kMaxCasters);
    gpu::Buffer& stream = mCasters[frame.slot()];
    if (!stream.valid())
        stream = gpu::Buffer(*mDevice, kMaxCasters * sizeof(glm::vec4), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                             gpu::MemoryUsage::CpuToGpu, "characterShadow.casters");
    std::memcpy(stream.mapped(), casters.data(), count * sizeof(glm::vec4));

    gpu::PassScope pass(frame, "terrain.characterShadows");
    VkCommandBuffer cmd = frame.cmd();
    const VkImageAspectFlags color = VK_IMAGE_ASPECT_COLOR_BIT;
    // Earlier frames' terrain passes sampled it.
    gpu::transitionImage(cmd, mMask.handle(), color, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    const VkRect2D whole{{0, 0}, {TS_CHARACTER_SHADOW_SIZE, TS_CHARACTER_SHADOW_SIZE}};
    gpu::beginColorRendering(cmd, mMask.view(), TS_CHARACTER_SHADOW_SIZE, TS_CHARACTER_SHADOW_SIZE, whole,
                             VK_ATTACHMENT_LOAD_OP_CLEAR);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
    shader::CharacterShadowParams params{};
    params.region = glm::vec4(region.x, region.y, region.z, 1.0f / region.z);
    params.sun = glm::vec4(glm::normalize(sun), kMaxShadowLength);
    vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof params, &params);
    const VkDeviceSize offset = 0;
    const VkBuffer buffer = stream.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
    vkCmdDraw(cmd, 6, uint32_t(count), 0, 0);
    vkCmdEndRendering(cmd);
    gpu::transitionImage(cmd, mMask.handle(), color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                         VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

} // namespace tessera::backends
