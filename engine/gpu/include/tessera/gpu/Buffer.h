#pragma once
/// @file Buffer.h
/// A named VkBuffer with its own memory.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace tessera::gpu {

class Device;

/// Where a buffer lives and who writes it.
enum class MemoryUsage {
    GpuOnly,  ///< device-local; filled through upload()
    CpuToGpu, ///< host-visible, coherent, persistently mapped (uniforms, streams)
    GpuToCpu, ///< host-visible, cached where possible (readbacks)
};

class Buffer {
public:
    Buffer() = default;
    Buffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory, std::string name);
    ~Buffer();
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    VkBuffer handle() const { return mBuffer; }
    VkDeviceSize size() const { return mSize; }
    bool valid() const { return mBuffer != VK_NULL_HANDLE; }
    /// Persistently mapped pointer for host-visible buffers, else null.
    void* mapped() const { return mMapped; }

    /// Copies `bytes` to the buffer at `offset`: directly when mapped, through
    /// a staging buffer and a blocking submit otherwise (load time only).
    void upload(std::span<const std::byte> bytes, VkDeviceSize offset = 0);
    template <class T>
    void upload(std::span<const T> items, VkDeviceSize offset = 0) {
        upload(std::as_bytes(items), offset);
    }

    /// Releases now; the caller guarantees the GPU is done with it.
    void reset();
    /// Releases once the frame now recording has retired.
    void deferredReset();

private:
    Device* mDevice = nullptr;
    VkBuffer mBuffer = VK_NULL_HANDLE;
    VkDeviceMemory mMemory = VK_NULL_HANDLE;
    VkDeviceSize mSize = 0;
    VkDeviceSize mAllocationSize = 0;
    void* mMapped = nullptr;
};

} // namespace tessera::gpu
