#pragma once
/// @file Buffer.h
/// A named VkBuffer with its own memory.

#include "tessera/gpu/UniqueHandle.h"

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
    /// Makes and names the buffer and its memory ("`name`.memory"). When the
    /// memory cannot be had (OutOfDeviceMemory), the buffer made first is
    /// destroyed before the exception leaves.
    Buffer(Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory, std::string name);
    ~Buffer() { reset(); }
    Buffer(Buffer&&) noexcept = default;
    Buffer& operator=(Buffer&&) noexcept = default;

    VkBuffer handle() const { return mBuffer.get(); }
    /// Bytes asked for (0 when empty).
    VkDeviceSize size() const { return valid() ? mSize : 0; }
    bool valid() const { return bool(mBuffer); }
    /// Persistently mapped pointer for host-visible buffers, else null.
    void* mapped() const { return valid() ? mMapped : nullptr; }

    /// Copies `bytes` to the buffer at `offset`: directly when mapped, through
    /// a staging buffer and a blocking submit otherwise (load time only).
    void upload(std::span<const std::byte> bytes, VkDeviceSize offset = 0);
    template <class T>
    void upload(std::span<const T> items, VkDeviceSize offset = 0) {
        upload(std::as_bytes(items), offset);
    }

    /// A host-visible transfer source named `name` holding a copy of `bytes`
    /// (non-empty): the staging of a load-time upload.
    static Buffer staging(Device& device, std::span<const std::byte> bytes, std::string name);

    /// Releases now; the caller guarantees the GPU is done with it.
    void reset();
    /// Releases once the frame now recording has retired.
    void deferredReset();

private:
    // In the order they are released in, by reset() and by a move
    // assignment's member-wise moves: the buffer, then its memory.
    UniqueHandle<VkBuffer, VK_OBJECT_TYPE_BUFFER> mBuffer;
    DeviceMemory mMemory;
    VkDeviceSize mSize = 0;
    void* mMapped = nullptr;
};

} // namespace tessera::gpu
