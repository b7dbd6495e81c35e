#include "tessera/gpu/UiRenderer.h"

#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/shaders/UiConstants.h"

#include "ui.frag.spv.h"
#include "ui.vert.spv.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace tessera::gpu {

UiRenderer::UiRenderer(Device& device, VkFormat colorFormat, VkFormat depthFormat, uint32_t fontWidth,
                       uint32_t fontHeight, std::span<const uint8_t> fontRgba)
    : mDevice(&device) {
    mLayout = PipelineLayout(device, {{TS_BINDING_UI_FONT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}},
                             sizeof(shader::UiConstants), VK_SHADER_STAGE_VERTEX_BIT, "overlay.layout");
    GraphicsPipelineDesc desc;
    desc.name = "overlay.pipeline";
    desc.layout = &mLayout;
    desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, ui_vert_spv}, {VK_SHADER_STAGE_FRAGMENT_BIT, ui_frag_spv}};
    desc.vertexBindings = {{0, sizeof(UiVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(UiVertex, x)},
                             {1, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(UiVertex, u)},
                             {2, 0, VK_FORMAT_R8G8B8A8_UNORM, offsetof(UiVertex, rgba)}};
    desc.cullMode = VK_CULL_MODE_NONE;
    // Drawn over the finished frame: no depth test, but the pass still has
    // the target's depth attachment, so the pipeline names its format.
    desc.depthTest = false;
    desc.depthWrite = false;
    desc.alphaBlend = true;
    desc.colorFormats = {colorFormat};
    desc.depthFormat = depthFormat;
    mPipeline = Pipeline(device, desc);

    ImageDesc font;
    font.width = fontWidth;
    font.height = fontHeight;
    font.format = VK_FORMAT_R8G8B8A8_UNORM;
    font.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    font.name = "overlay.font";
    mFont = Image(device, font);
    mFont.upload(std::as_bytes(fontRgba), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    mSampler = Sampler(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, "overlay.sampler");
}

void UiRenderer::reserve(Buffer& buffer, VkDeviceSize bytes, VkBufferUsageFlags usage, const char* name) {
    if (buffer.valid() && buffer.size() >= bytes) return;
    // Grow by half again so a window that keeps growing does not reallocate
    // every frame.
    const VkDeviceSize size = std::max<VkDeviceSize>(bytes + bytes / 2, 64 * 1024);
    buffer = Buffer(*mDevice, size, usage, MemoryUsage::CpuToGpu, name);
}

void UiRenderer::record(FrameContext& frame, const UiDrawData& data) {
    if (!valid() || data.commands.empty() || data.displayWidth <= 0.0f || data.displayHeight <= 0.0f) return;
    Buffer& vertices = mVertices[frame.slot()];
    Buffer& indices = mIndices[frame.slot()];
    reserve(vertices, data.vertices.size_bytes(), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "overlay.vertices");
    reserve(indices, data.indices.size_bytes(), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "overlay.indices");
    std::memcpy(vertices.mapped(), data.vertices.data(), data.vertices.size_bytes());
    std::memcpy(indices.mapped(), data.indices.data(), data.indices.size_bytes());

    RenderTarget& target = frame.target();
    VkCommandBuffer cmd = frame.cmd();
    target.resumeRendering(cmd);
    {
        PassScope pass(frame, "overlay");
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.handle());
        VkDescriptorImageInfo fontInfo{mSampler.handle(), mFont.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        write.dstBinding = TS_BINDING_UI_FONT;
        write.descriptorCount = 1;
        write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        write.pImageInfo = &fontInfo;
        mDevice->fn().cmdPushDescriptorSet(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout.handle(), 0, 1, &write);
        shader::UiConstants push{};
        const float sx = 2.0f / data.displayWidth, sy = 2.0f / data.displayHeight;
        push.transform = glm::vec4(sx, sy, -1.0f - data.displayX * sx, -1.0f - data.displayY * sy);
        vkCmdPushConstants(cmd, mLayout.handle(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(push), &push);
        const VkDeviceSize offset = 0;
        const VkBuffer vb = vertices.handle();
        vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
        vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT16);
        // The display maps onto the whole target; clip rectangles scale with it.
        const float scaleX = float(target.width()) / data.displayWidth;
        const float scaleY = float(target.height()) / data.displayHeight;
        for (const UiDrawCommand& c : data.commands) {
            const float x0 = std::clamp((c.clipMinX - data.displayX) * scaleX, 0.0f, float(target.width()));
            const float y0 = std::clamp((c.clipMinY - data.displayY) * scaleY, 0.0f, float(target.height()));
            const float x1 = std::clamp((c.clipMaxX - data.displayX) * scaleX, 0.0f, float(target.width()));
            const float y1 = std::clamp((c.clipMaxY - data.displayY) * scaleY, 0.0f, float(target.height()));
            if (x1 <= x0 || y1 <= y0 || c.indexCount == 0) continue;
            VkRect2D scissor{{int32_t(x0), int32_t(y0)},
                             {uint32_t(std::ceil(x1) - std::floor(x0)), uint32_t(std::ceil(y1) - std::floor(y0))}};
            scissor.extent.width = std::min(scissor.extent.width, target.width() - uint32_t(scissor.offset.x));
            scissor.extent.height = std::min(scissor.extent.height, target.height() - uint32_t(scissor.offset.y));
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            vkCmdDrawIndexed(cmd, c.indexCount, 1, c.firstIndex, c.vertexOffset, 0);
        }
    }
    target.endRendering(cmd);
}

} // namespace tessera::gpu
