#include "R2vbRecording.h"

#include "shaders/R2vbLayout.h"

#include <utility>
#include <vector>

namespace tessera::backends::r2vb {

gpu::GraphicsPipelineDesc pointPipeline(const std::string& name, const gpu::PipelineLayout& layout,
                                        std::span<const uint32_t> vertexSpirv, std::span<const uint32_t> fragmentSpirv,
                                        std::vector<VkFormat> colorFormats) {
    gpu::GraphicsPipelineDesc desc;
    desc.name = name;
    desc.layout = &layout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, vertexSpirv}, {VK_SHADER_STAGE_FRAGMENT_BIT, fragmentSpirv}};
    desc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    desc.cullMode = VK_CULL_MODE_NONE;
    desc.depthTest = false;
    desc.depthWrite = false;
    desc.colorFormats = std::move(colorFormats);
    return desc;
}

VkImageMemoryBarrier2 imageBarrier(const gpu::Image& image, VkImageLayout from, VkImageLayout to,
                                   VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image.handle();
    barrier.subresourceRange = {image.aspect(), 0, 1, 0, 1};
    return barrier;
}

VkBufferMemoryBarrier2 bufferBarrier(const gpu::Buffer& buffer, VkPipelineStageFlags2 srcStage,
                                     VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                                     VkAccessFlags2 dstAccess) {
    VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.buffer = buffer.handle();
    barrier.offset = 0;
    barrier.size = VK_WHOLE_SIZE;
    return barrier;
}

void barriers(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> images,
              std::span<const VkBufferMemoryBarrier2> buffers) {
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = static_cast<uint32_t>(images.size());
    dependency.pImageMemoryBarriers = images.data();
    dependency.bufferMemoryBarrierCount = static_cast<uint32_t>(buffers.size());
    dependency.pBufferMemoryBarriers = buffers.data();
    vkCmdPipelineBarrier2(cmd, &dependency);
}

void beginPoints(VkCommandBuffer cmd, std::span<gpu::Image* const> targets, uint32_t rows,
                 const gpu::PipelineLayout& layout) {
    const uint32_t width = targets.front()->width();
    const uint32_t height = targets.front()->height();
    std::vector<VkRenderingAttachmentInfo> attachments(targets.size());
    for (size_t i = 0; i < targets.size(); ++i) {
        VkRenderingAttachmentInfo& a = attachments[i];
        a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
        a.imageView = targets[i]->view();
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        // Cleared so a texel no point lands on reads as zero: for a command
        // target that is an indirect draw of nothing.
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.clearValue.color = {};
    }
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {width, rows}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = static_cast<uint32_t>(attachments.size());
    rendering.pColorAttachments = attachments.data();
    vkCmdBeginRendering(cmd, &rendering);
    const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &rendering.renderArea);
    const shader::R2vbTargetConstants constants{glm::uvec4(width, height, 0u, 0u)};
    vkCmdPushConstants(cmd, layout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof constants, &constants);
}

void copyRows(VkCommandBuffer cmd, const gpu::Image& image, uint32_t rows, const gpu::Buffer& buffer,
              VkDeviceSize offset) {
    VkBufferImageCopy region{};
    region.bufferOffset = offset;
    region.imageSubresource = {image.aspect(), 0, 0, 1};
    region.imageExtent = {image.width(), rows, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(), 1, &region);
}

} // namespace tessera::backends::r2vb
