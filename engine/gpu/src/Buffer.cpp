#include "tessera/gpu/Buffer.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <cassert>
#include <cstring>
#include <utility>

namespace tessera::gpu {

Buffer::Buffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory, std::string name)
    : mSize(size) {
    assert(size > 0);
    if (memory == MemoryUsage::GpuOnly) usage |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateBuffer(device.handle(), &info, nullptr, &buffer));
    mBuffer = {device, buffer, name};

    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device.handle(), buffer, &req);
    VkMemoryPropertyFlags flags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (memory == MemoryUsage::CpuToGpu) flags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    if (memory == MemoryUsage::GpuToCpu)
        flags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
    // If this throws, mBuffer (complete) is destroyed with the half-built object.
    mMemory = device.allocate(req, flags, name);
    TESSERA_VK_CHECK(vkBindBufferMemory(device.handle(), buffer, mMemory.get(), 0));
    if (memory != MemoryUsage::GpuOnly)
        TESSERA_VK_CHECK(vkMapMemory(device.handle(), mMemory.get(), 0, VK_WHOLE_SIZE, 0, &mMapped));
}

Buffer Buffer::staging(Device& device, std::span<const std::byte> bytes, std::string name) {
    Buffer buffer(device, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::CpuToGpu, std::move(name));
    std::memcpy(buffer.mapped(), bytes.data(), bytes.size());
    return buffer;
}

void Buffer::reset() {
    mBuffer.reset();
    mMemory.reset();
    mMapped = nullptr;
}

void Buffer::deferredReset() {
    Device* device = mBuffer.device();
    if (!device) return;
    // This object is empty from here on.
    device->deferRelease(std::move(*this));
}

void Buffer::upload(std::span<const std::byte> bytes, VkDeviceSize offset) {
    assert(offset + bytes.size() <= mSize);
    if (bytes.empty()) return;
    if (mapped()) {
        std::memcpy(static_cast<std::byte*>(mapped()) + offset, bytes.data(), bytes.size());
        return;
    }
    Device& device = *mBuffer.device();
    const Buffer source = staging(device, bytes, "staging.buffer");
    device.submitImmediate(
        [&](VkCommandBuffer cmd) {
            VkBufferCopy region{0, offset, bytes.size()};
            vkCmdCopyBuffer(cmd, source.handle(), handle(), 1, &region);
        },
        "upload.buffer");
}

} // namespace tessera::gpu
