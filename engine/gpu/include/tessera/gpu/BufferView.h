#pragma once
/// @file BufferView.h
/// A named VkBufferView: a formatted view of a buffer, read in shaders as a
/// texel buffer (D3D10's Buffer<float4>.Load, and the closest thing Vulkan
/// has to D3D9's vertex texture fetch from an R2VB buffer).

#include <vulkan/vulkan.h>

#include <string>

namespace tessera::gpu {

class Buffer;
class Device;

class BufferView {
public:
    BufferView() = default;
    /// Views `range` bytes of `buffer` from `offset` as `format` texels. The
    /// buffer needs a texel-buffer usage bit for that format.
    BufferView(Device& device, const Buffer& buffer, VkFormat format, VkDeviceSize offset, VkDeviceSize range,
               std::string name);
    ~BufferView();
    BufferView(BufferView&& other) noexcept;
    BufferView& operator=(BufferView&& other) noexcept;
    BufferView(const BufferView&) = delete;
    BufferView& operator=(const BufferView&) = delete;

    VkBufferView handle() const { return mView; }
    bool valid() const { return mView != VK_NULL_HANDLE; }

private:
    Device* mDevice = nullptr;
    VkBufferView mView = VK_NULL_HANDLE;
};

} // namespace tessera::gpu
