#include "tessera/gpu/Buffer.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <cassert>
#include <cstring>
#include <utility>

namespace tessera::gpu {

Buffer::Buffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory, std::string name)
    : mDevice(&device), mSize(size) {
    assert(size > 0);
    if (memory == MemoryUsage::GpuOnly) usage |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    TESSERA_VK_CHECK(vkCreateBuffer(device.handle(), &info, nullptr, &mBuffer));
    device.setName(VK_OBJECT_TYPE_BUFFER, mBuffer, name);

    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device.handle(), mBuffer, &req);
    VkMemoryPropertyFlags flags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    if (memory == MemoryUsage::CpuToGpu) flags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    if (memory == MemoryUsage::GpuToCpu)
        flags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
    try {
        mMemory = device.allocate(req, flags, name);
    } catch (...) {
        reset(); // the buffer made above; the destructor does not run for a constructor that throws
        throw;
    }
    mAllocationSize = req.size;
    TESSERA_VK_CHECK(vkBindBufferMemory(device.handle(), mBuffer, mMemory, 0));
    if (memory != MemoryUsage::GpuOnly) TESSERA_VK_CHECK(vkMapMemory(device.handle(), mMemory, 0, VK_WHOLE_SIZE, 0, &mMapped));
}

Buffer::~Buffer() { reset(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        reset();
        mDevice = std::exchange(other.mDevice, nullptr);
        mBuffer = std::exchange(other.mBuffer, VK_NULL_HANDLE);
        mMemory = std::exchange(other.mMemory, VK_NULL_HANDLE);
        mSize = std::exchange(other.mSize, 0);
        mAllocationSize = std::exchange(other.mAllocationSize, 0);
        mMapped = std::exchange(other.mMapped, nullptr);
    }
    return *this;
}

void Buffer::reset() {
    if (!mDevice) return;
    mDevice->clearName(VK_OBJECT_TYPE_BUFFER, mBuffer);
    vkDestroyBuffer(mDevice->handle(), mBuffer, nullptr);
    mDevice->free(mMemory, mAllocationSize);
    mDevice = nullptr;
    mBuffer = VK_NULL_HANDLE;
    mMemory = VK_NULL_HANDLE;
    mMapped = nullptr;
}

void Buffer::deferredReset() {
    if (!mDevice) return;
    // Move the handles into a heap copy whose destructor runs once the frame
    // now recording has retired; this object is empty from here on.
    auto* doomed = new Buffer(std::move(*this));
    doomed->mDevice->deferDestroy([doomed] { delete doomed; });
}

void Buffer::upload(std::span<const std::byte> bytes, VkDeviceSize offset) {
    assert(offset + bytes.size() <= mSize);
    if (bytes.empty()) return;
    if (mMapped) {
        std::memcpy(static_cast<std::byte*>(mMapped) + offset, bytes.data(), bytes.size());
        return;
    }
    Buffer staging(*mDevice, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::CpuToGpu, "staging.buffer");
    std::memcpy(staging.mapped(), bytes.data(), bytes.size());
    mDevice->submitImmediate(
        [&](VkCommandBuffer cmd) {
            VkBufferCopy region{0, offset, bytes.size()};
            vkCmdCopyBuffer(cmd, staging.handle(), mBuffer, 1, &region);
        },
        "upload.buffer");
}

} // namespace tessera::gpu
