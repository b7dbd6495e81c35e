#include "tessera/gpu/Image.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <cstring>
#include <utility>

namespace tessera::gpu {
namespace {

bool isDepthFormat(VkFormat f) {
    return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

} // namespace

Image::Image(Device& device, const ImageDesc& desc) : mDevice(&device), mDesc(desc) {
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
    TESSERA_VK_CHECK(vkCreateImage(device.handle(), &info, nullptr, &mImage));
    device.setName(VK_OBJECT_TYPE_IMAGE, mImage, desc.name);

    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device.handle(), mImage, &req);
    try {
        mMemory = device.allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, desc.name);
    } catch (...) {
        reset(); // the image made above; the destructor does not run for a constructor that throws
        throw;
    }
    mAllocationSize = req.size;
    TESSERA_VK_CHECK(vkBindImageMemory(device.handle(), mImage, mMemory, 0));

    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = mImage;
    view.viewType = desc.arrayLayers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    view.format = desc.format;
    view.subresourceRange = {aspect(), 0, desc.mipLevels, 0, desc.arrayLayers};
    TESSERA_VK_CHECK(vkCreateImageView(device.handle(), &view, nullptr, &mView));
    device.setName(VK_OBJECT_TYPE_IMAGE_VIEW, mView, desc.name + ".view");
    if (desc.aliasFormat != VK_FORMAT_UNDEFINED) {
        view.format = desc.aliasFormat;
        TESSERA_VK_CHECK(vkCreateImageView(device.handle(), &view, nullptr, &mAliasView));
        device.setName(VK_OBJECT_TYPE_IMAGE_VIEW, mAliasView, desc.name + ".aliasView");
    }
}

VkImageAspectFlags Image::aspect() const {
    return isDepthFormat(mDesc.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

Image::~Image() { reset(); }

Image::Image(Image&& other) noexcept { *this = std::move(other); }

Image& Image::operator=(Image&& other) noexcept {
    if (this != &other) {
        reset();
        mDevice = std::exchange(other.mDevice, nullptr);
        mDesc = other.mDesc;
        mImage = std::exchange(other.mImage, VK_NULL_HANDLE);
        mView = std::exchange(other.mView, VK_NULL_HANDLE);
        mAliasView = std::exchange(other.mAliasView, VK_NULL_HANDLE);
        mMemory = std::exchange(other.mMemory, VK_NULL_HANDLE);
        mAllocationSize = std::exchange(other.mAllocationSize, 0);
    }
    return *this;
}

void Image::reset() {
    if (!mDevice) return;
    mDevice->clearName(VK_OBJECT_TYPE_IMAGE_VIEW, mView);
    vkDestroyImageView(mDevice->handle(), mView, nullptr);
    if (mAliasView) {
        mDevice->clearName(VK_OBJECT_TYPE_IMAGE_VIEW, mAliasView);
        vkDestroyImageView(mDevice->handle(), mAliasView, nullptr);
    }
    mDevice->clearName(VK_OBJECT_TYPE_IMAGE, mImage);
    vkDestroyImage(mDevice->handle(), mImage, nullptr);
    mDevice->free(mMemory, mAllocationSize);
    mDevice = nullptr;
    mImage = VK_NULL_HANDLE;
    mView = VK_NULL_HANDLE;
    mAliasView = VK_NULL_HANDLE;
    mMemory = VK_NULL_HANDLE;
}

void Image::deferredReset() {
    if (!mDevice) return;
    // Move the handles into a heap copy whose destructor runs once the frame
    // now recording has retired; this object is empty from here on.
    auto* doomed = new Image(std::move(*this));
    doomed->mDevice->deferDestroy([doomed] { delete doomed; });
}

void Image::upload(std::span<const std::byte> texels, VkImageLayout finalLayout) {
    Buffer staging(*mDevice, texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::CpuToGpu,
                   mDesc.name + ".staging");
    std::memcpy(staging.mapped(), texels.data(), texels.size());
    mDevice->submitImmediate(
        [&](VkCommandBuffer cmd) {
            transitionImage(cmd, mImage, aspect(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT, mDesc.mipLevels);
            VkBufferImageCopy region{};
            region.imageSubresource = {aspect(), 0, 0, 1};
            region.imageExtent = {mDesc.width, mDesc.height, 1};
            vkCmdCopyBufferToImage(cmd, staging.handle(), mImage, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
            transitionImage(cmd, mImage, aspect(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, finalLayout,
                            VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                            VK_ACCESS_2_MEMORY_READ_BIT, mDesc.mipLevels);
        },
        "upload.image");
}

void Image::upload(std::span<const std::byte> texels, std::span<const VkBufferImageCopy> regions,
                   VkImageLayout finalLayout) {
    Buffer staging(*mDevice, texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::CpuToGpu,
                   mDesc.name + ".staging");
    std::memcpy(staging.mapped(), texels.data(), texels.size());
    mDevice->submitImmediate(
        [&](VkCommandBuffer cmd) {
            // imageBarrier covers every mip given and every layer of the image.
            const VkImageMemoryBarrier2 toCopy[] = {imageBarrier(
                *this, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
                VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, mDesc.mipLevels)};
            pipelineBarrier(cmd, toCopy);
            vkCmdCopyBufferToImage(cmd, staging.handle(), mImage, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
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
