#pragma once
/// @file Image.h
/// A named 2D VkImage with one view and its own memory, plus the layout
/// transition helper every pass uses.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <string>

namespace tessera::gpu {

class Device;

struct ImageDesc {
    uint32_t width = 1;
    uint32_t height = 1;
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    uint32_t mipLevels = 1;
    /// More than one: a 2D array image with a 2D_ARRAY view over every layer.
    uint32_t arrayLayers = 1;
    /// When set, a second view in this size-compatible format (the image is
    /// created MUTABLE_FORMAT), e.g. R16_UINT over R16_UNORM to read and
    /// write exact bits where the UNORM conversion's rounding is not defined
    /// tightly enough.
    VkFormat aliasFormat = VK_FORMAT_UNDEFINED;
    std::string name;
};

class Image {
public:
    Image() = default;
    Image(Device& device, const ImageDesc& desc);
    ~Image();
    Image(Image&& other) noexcept;
    Image& operator=(Image&& other) noexcept;
    Image(const Image&) = delete;
    Image& operator=(const Image&) = delete;

    VkImage handle() const { return mImage; }
    VkImageView view() const { return mView; }
    /// The view in ImageDesc::aliasFormat (VK_NULL_HANDLE without one).
    VkImageView aliasView() const { return mAliasView; }
    VkFormat format() const { return mDesc.format; }
    uint32_t width() const { return mDesc.width; }
    uint32_t height() const { return mDesc.height; }
    uint32_t mipLevels() const { return mDesc.mipLevels; }
    uint32_t arrayLayers() const { return mDesc.arrayLayers; }
    VkImageAspectFlags aspect() const;
    bool valid() const { return mImage != VK_NULL_HANDLE; }

    /// Uploads mip 0 from tightly packed texels and leaves the image in
    /// `finalLayout`. Blocking; load time only.
    void upload(std::span<const std::byte> texels, VkImageLayout finalLayout);
    /// Uploads `texels` into the subresources `regions` name (offsets into
    /// `texels`; mips and layers of an array, e.g.) and leaves every mip and
    /// layer in `finalLayout`. Blocking; load time only.
    void upload(std::span<const std::byte> texels, std::span<const VkBufferImageCopy> regions,
                VkImageLayout finalLayout);

    void reset();
    void deferredReset();

private:
    Device* mDevice = nullptr;
    ImageDesc mDesc;
    VkImage mImage = VK_NULL_HANDLE;
    VkImageView mView = VK_NULL_HANDLE;
    VkImageView mAliasView = VK_NULL_HANDLE;
    VkDeviceMemory mMemory = VK_NULL_HANDLE;
    VkDeviceSize mAllocationSize = 0;
};

/// Records a full-image layout transition with synchronization2 barriers.
/// Stages and accesses are given explicitly so each pass states what it needs.
/// One barrier on its own; imageBarrier and pipelineBarrier (Barriers.h)
/// record several images and buffers at once.
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                     VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                     VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, uint32_t mipLevels = 1);

} // namespace tessera::gpu
