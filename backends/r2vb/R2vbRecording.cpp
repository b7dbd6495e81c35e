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

void beginTargets(VkCommandBuffer cmd, std::span<gpu::Image* const> targets, const VkRect2D& area,
                  const VkViewport& viewport, VkClearColorValue clear) {
    std::vector<VkRenderingAttachmentInfo> attachments(targets.size());
    for (size_t i = 0; i < targets.size(); ++i) {
        VkRenderingAttachmentInfo& a = attachments[i];
        a.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO;
        a.imageView = targets[i]->view();
        a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        // Cleared so a texel no point lands on reads as nothing: zero
        // levels, no counts, no entry, an unused slot, an indirect draw of
        // no vertices.
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.clearValue.color = clear;
    }
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = area;
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = static_cast<uint32_t>(attachments.size());
    rendering.pColorAttachments = attachments.data();
    vkCmdBeginRendering(cmd, &rendering);
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &area);
}

void beginPoints(VkCommandBuffer cmd, std::span<gpu::Image* const> targets, uint32_t rows,
                 const gpu::PipelineLayout& layout) {
    const uint32_t width = targets.front()->width();
    const uint32_t height = targets.front()->height();
    beginTargets(cmd, targets, {{0, 0}, {width, rows}}, {0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f}, {});
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
