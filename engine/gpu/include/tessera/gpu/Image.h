#pragma once
/// @file Image.h
/// A named 2D VkImage with one view and its own memory, plus the layout
/// transition helper every pass uses.

#include "tessera/gpu/UniqueHandle.h"

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
    /// Makes and names the image, its memory ("`name`.memory") and its views.
    /// When the memory cannot be had (OutOfDeviceMemory), the image made
    /// first is destroyed before the exception leaves.
    Image(Device& device, const ImageDesc& desc);
    ~Image() { reset(); }
    Image(Image&&) noexcept = default;
    Image& operator=(Image&&) noexcept = default;

    VkImage handle() const { return mImage.get(); }
    VkImageView view() const { return mView.get(); }
    /// The view in ImageDesc::aliasFormat (VK_NULL_HANDLE without one).
    VkImageView aliasView() const { return mAliasView.get(); }
    VkFormat format() const { return mDesc.format; }
    uint32_t width() const { return mDesc.width; }
    uint32_t height() const { return mDesc.height; }
    uint32_t mipLevels() const { return mDesc.mipLevels; }
    uint32_t arrayLayers() const { return mDesc.arrayLayers; }
    VkImageAspectFlags aspect() const;
    bool valid() const { return bool(mImage); }

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
    ImageDesc mDesc;
    // In the order they are released in, by reset() and by a move
    // assignment's member-wise moves: the views, the image, its memory.
    UniqueHandle<VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW> mAliasView;
    UniqueHandle<VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW> mView;
    UniqueHandle<VkImage, VK_OBJECT_TYPE_IMAGE> mImage;
    DeviceMemory mMemory;
};

/// Records a full-image layout transition with synchronization2 barriers.
/// Stages and accesses are given explicitly so each pass states what it needs.
/// One barrier on its own; imageBarrier and pipelineBarrier (Barriers.h)
/// record several images and buffers at once.
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                     VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                     VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, uint32_t mipLevels = 1);

} // namespace tessera::gpu
