#include "R2vbCrowdRecording.h"

#include "R2vbRecording.h"
#include "tessera/shaders/CrowdInstance.h"
#include "tessera/gpu/Barriers.h"

namespace tessera::backends::r2vb::crowd {
namespace {

constexpr VkPipelineStageFlags2 kShaders =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kOutput = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags2 kOutputWrite = VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;

VkDeviceSize texelBytes(VkFormat format) {
    return format == VK_FORMAT_R32G32B32A32_UINT ? 16 : 4;
}

} // namespace

gpu::PipelineLayout layout(gpu::Device& device, std::string name) {
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    const VkDescriptorType texels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    const VkDescriptorType image = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    return gpu::PipelineLayout(device,
                               {{TS_BINDING_CROWD, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, stages},
                                {TS_BINDING_CROWD_INSTANCES, texels, stages},
                                {TS_BINDING_CROWD_BAKED, texels, stages},
                                {TS_BINDING_CROWD_CLIPS, texels, stages},
                                {TS_BINDING_CROWD_SLOTS, texels, stages},
                                {TS_BINDING_CROWD_OCCLUDERS, texels, stages},
                                {R2VB_CROWD_BINDING_STATE, image, stages},
                                {R2VB_CROWD_BINDING_EVEN, image, stages},
                                {R2VB_CROWD_BINDING_ODD, image, stages},
                                {R2VB_CROWD_BINDING_SOURCE, image, stages}},
                               sizeof(shader::R2vbCrowdConstants), stages, std::move(name));
}

void push(gpu::Device& device, VkCommandBuffer cmd, const gpu::PipelineLayout& layout,
          std::span<const VkWriteDescriptorSet> writes, const shader::R2vbCrowdConstants& constants) {
    device.fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.handle(), 0, uint32_t(writes.size()),
                                     writes.data());
    vkCmdPushConstants(cmd, layout.handle(), layout.pushConstantStages(), 0, sizeof constants, &constants);
}

void beginArea(VkCommandBuffer cmd, std::span<gpu::Image* const> targets, VkRect2D area, VkClearColorValue clear) {
    const VkViewport viewport{
        float(area.offset.x), float(area.offset.y), float(area.extent.width), float(area.extent.height), 0.0f, 1.0f};
    beginTargets(cmd, targets, area, viewport, clear);
}

void beginWhole(VkCommandBuffer cmd, std::span<gpu::Image* const> targets) {
    beginArea(cmd, targets, {{0, 0}, {targets.front()->width(), targets.front()->height()}}, {});
}

void toTarget(VkCommandBuffer cmd, const gpu::Image& image, VkPipelineStageFlags2 lastUse) {
    gpu::transitionImage(cmd, image.handle(), image.aspect(), VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, lastUse, VK_ACCESS_2_NONE, kOutput, kOutputWrite);
}

void renderedToSampled(VkCommandBuffer cmd, const gpu::Image& image) {
    gpu::transitionImage(cmd, image.handle(), image.aspect(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kOutput, kOutputWrite, kShaders,
                         VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

void sampledToTarget(VkCommandBuffer cmd, const gpu::Image& image) {
    gpu::transitionImage(cmd, image.handle(), image.aspect(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                         VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, kShaders, VK_ACCESS_2_NONE, kOutput,
                         VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | kOutputWrite);
}

void renderedToCopy(VkCommandBuffer cmd, const gpu::Image& image) {
    gpu::transitionImage(cmd, image.handle(), image.aspect(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, kOutput, kOutputWrite, VK_PIPELINE_STAGE_2_COPY_BIT,
                         VK_ACCESS_2_TRANSFER_READ_BIT);
}

void appendCopy(std::vector<VkBufferImageCopy>& regions, const gpu::Image& image, uint32_t firstRow, uint64_t texels,
                VkDeviceSize offset) {
    const uint32_t width = image.width();
    const uint32_t rows = uint32_t(texels / width);
    const uint32_t rest = uint32_t(texels % width);
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect(), 0, 0, 1};
    if (rows > 0) {
        region.bufferOffset = offset;
        region.imageOffset = {0, int32_t(firstRow), 0};
        region.imageExtent = {width, rows, 1};
        regions.push_back(region);
    }
    if (rest > 0) {
        region.bufferOffset = offset + VkDeviceSize(rows) * width * texelBytes(image.format());
        region.imageOffset = {0, int32_t(firstRow + rows), 0};
        region.imageExtent = {rest, 1, 1};
        regions.push_back(region);
    }
}

void copy(VkCommandBuffer cmd, const gpu::Image& image, const gpu::Buffer& buffer,
          std::span<const VkBufferImageCopy> regions) {
    if (regions.empty()) return;
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(),
                           uint32_t(regions.size()), regions.data());
}

void copiesToReaders(VkCommandBuffer cmd) {
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT |
                           VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                           VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                       VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT |
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT |
                           VK_ACCESS_2_TRANSFER_WRITE_BIT);
}

} // namespace tessera::backends::r2vb::crowd
