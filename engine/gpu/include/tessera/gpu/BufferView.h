#pragma once
/// @file BufferView.h
/// A named VkBufferView: a formatted view of a buffer, read in shaders as a
/// texel buffer (D3D10's Buffer<float4>.Load, and the closest thing Vulkan
/// has to D3D9's vertex texture fetch from an R2VB buffer).

#include "tessera/gpu/UniqueHandle.h"

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

    VkBufferView handle() const { return mView.get(); }
    bool valid() const { return bool(mView); }

private:
    UniqueHandle<VkBufferView, VK_OBJECT_TYPE_BUFFER_VIEW> mView;
};

} // namespace tessera::gpu
