#include "tessera/gpu/Image.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <utility>

namespace tessera::gpu {
namespace {

bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

} // namespace

Image::Image(Device& device, const ImageDesc& desc) : mDesc(desc) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.arrayLayers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    if (desc.aliasFormat != VK_FORMAT_UNDEFINED) info.flags |= VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
    VkImage image = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateImage(device.handle(), &info, nullptr, &image));
    mImage = {device, image, desc.name};

    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device.handle(), image, &req);
    // If this throws, mImage (complete) is destroyed with the half-built object.
    mMemory = device.allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, desc.name);
    TESSERA_VK_CHECK(vkBindImageMemory(device.handle(), image, mMemory.get(), 0));

    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = desc.arrayLayers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    view.format = desc.format;
    view.subresourceRange = {aspect(), 0, desc.mipLevels, 0, desc.arrayLayers};
    VkImageView created = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateImageView(device.handle(), &view, nullptr, &created));
    mView = {device, created, desc.name + ".view"};
    if (desc.aliasFormat != VK_FORMAT_UNDEFINED) {
        view.format = desc.aliasFormat;
        TESSERA_VK_CHECK(vkCreateImageView(device.handle(), &view, nullptr, &created));
        mAliasView = {device, created, desc.name + ".aliasView"};
    }
}

VkImageAspectFlags Image::aspect() const {
    return isDepthFormat(mDesc.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

void Image::reset() {
    mAliasView.reset();
    mView.reset();
    mImage.reset();
    mMemory.reset();
}

void Image::deferredReset() {
    Device* device = mImage.device();
    if (!device) return;
    // This object is empty from here on.
    device->deferRelease(std::move(*this));
}

void Image::upload(std::span<const std::byte> texels, VkImageLayout finalLayout) {
    Device& device = *mImage.device();
    const Buffer staging = Buffer::staging(device, texels, mDesc.name + ".staging");
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            transitionImage(cmd, handle(), aspect(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT, mDesc.mipLevels);
            VkBufferImageCopy region{};
            region.imageSubresource = {aspect(), 0, 0, 1};
            region.imageExtent = {mDesc.width, mDesc.height, 1};
            vkCmdCopyBufferToImage(cmd, staging.handle(), handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            transitionImage(cmd, handle(), aspect(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, finalLayout,
                            VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                            VK_ACCESS_2_MEMORY_READ_BIT, mDesc.mipLevels);
        },
        "upload.image");
}

void Image::upload(std::span<const std::byte> texels, std::span<const VkBufferImageCopy> regions,
                   VkImageLayout finalLayout) {
    Device& device = *mImage.device();
    const Buffer staging = Buffer::staging(device, texels, mDesc.name + ".staging");
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            // imageBarrier covers every mip given and every layer of the image.
            const VkImageMemoryBarrier2 toCopy[] = {imageBarrier(
                *this, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, mDesc.mipLevels)};
            pipelineBarrier(cmd, toCopy);
            vkCmdCopyBufferToImage(cmd, staging.handle(), handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                   static_cast<uint32_t>(regions.size()), regions.data());
            const VkImageMemoryBarrier2 toFinal[] = {
                imageBarrier(*this, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, finalLayout, VK_PIPELINE_STAGE_2_COPY_BIT,
                             VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                             VK_ACCESS_2_MEMORY_READ_BIT, mDesc.mipLevels)};
            pipelineBarrier(cmd, toFinal);
        },
        "upload.imageRegions");
}

} // namespace tessera::gpu
