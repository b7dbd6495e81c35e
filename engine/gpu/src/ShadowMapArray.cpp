#include "tessera/gpu/ShadowMapArray.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

namespace tessera::gpu {

ShadowMapArray::ShadowMapArray(Device& device, uint32_t size, uint32_t layers, const std::string& name) {
    ImageDesc desc;
    desc.width = size;
    desc.height = size;
    desc.format = kFormat;
    desc.arrayLayers = layers;
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                 VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    desc.name = name;
    mImage = Image(device, desc);
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = mImage.handle();
    view.format = kFormat;
    VkImageView created = VK_NULL_HANDLE;
    // Its own array view even for one layer (Image's would be 2D): the
    // shaders read a sampler2DArrayShadow whatever the cascade count.
    view.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
    TESSERA_VK_CHECK(vkCreateImageView(device.handle(), &view, nullptr, &created));
    mLayerViews.emplace_back(device, created, name + ".arrayView");
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    for (uint32_t layer = 0; layer < layers; ++layer) {
        view.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, layer, 1};
        TESSERA_VK_CHECK(vkCreateImageView(device.handle(), &view, nullptr, &created));
        mLayerViews.emplace_back(device, created, name + ".layer" + std::to_string(layer));
    }
    mSampler = Sampler(device, VK_FILTER_LINEAR, VK_COMPARE_OP_LESS_OR_EQUAL, name + ".sampler");
    // Cleared to the far depth, so a frame that draws no casters reads "lit".
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            const VkImageMemoryBarrier2 toClear[1] = {
                imageBarrier(mImage, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                             VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_CLEAR_BIT,
                             VK_ACCESS_2_TRANSFER_WRITE_BIT)};
            pipelineBarrier(cmd, toClear);
            const VkClearDepthStencilValue far{1.0f, 0};
            const VkImageSubresourceRange all{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
            vkCmdClearDepthStencilImage(cmd, mImage.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &far, 1, &all);
            const VkImageMemoryBarrier2 toRead[1] = {
                imageBarrier(mImage, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                             VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                             VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT)};
            pipelineBarrier(cmd, toRead);
        },
        "shadowMapArray.clear");
}

void ShadowMapArray::beginWriting(VkCommandBuffer cmd, VkPipelineStageFlags2 readStages, Contents contents) const {
    // Clearing: from UNDEFINED, as every layer is cleared by its pass and
    // the old texels need not survive the transition. Keeping: from the
    // sampled layout, which preserves them.
    const VkImageLayout from =
        contents == Contents::Clear ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const VkImageMemoryBarrier2 barrier[1] = {imageBarrier(
        mImage, from, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, readStages, 0,
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)};
    pipelineBarrier(cmd, barrier);
}

void ShadowMapArray::beginLayer(VkCommandBuffer cmd, uint32_t layer, Contents contents) const {
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = mLayerViews.at(1 + layer).get();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = contents == Contents::Clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, {size(), size()}};
    info.layerCount = 1;
    info.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &info);
    const VkViewport viewport{0.0f, 0.0f, float(size()), float(size()), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &info.renderArea);
}

void ShadowMapArray::endLayer(VkCommandBuffer cmd) const { vkCmdEndRendering(cmd); }

void ShadowMapArray::endWriting(VkCommandBuffer cmd, VkPipelineStageFlags2 readStages) const {
    const VkImageMemoryBarrier2 barrier[1] = {
        imageBarrier(mImage, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                     VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                     readStages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT)};
    pipelineBarrier(cmd, barrier);
}

VkDescriptorImageInfo ShadowMapArray::descriptor() const {
    return {mSampler.handle(), mLayerViews.front().get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

} // namespace tessera::gpu
