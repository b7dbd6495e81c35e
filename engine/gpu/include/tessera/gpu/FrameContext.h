#pragma once
/// @file FrameContext.h
/// Everything a backend records a frame with: the command buffer, the target,
/// a per-frame uniform allocator and the pass markers that feed the profiler.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace tessera::gpu {

class Device;
class GpuProfiler;
class RenderTarget;
class Buffer;

/// A slice of the frame's uniform ring, valid until the frame retires.
struct UniformSlice {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = 0;
    void* data = nullptr;
    VkDescriptorBufferInfo descriptor() const { return {buffer, offset, size}; }
};

class FrameContext {
public:
    FrameContext(Device& device, GpuProfiler& profiler, RenderTarget& target, Buffer& uniformRing,
                 VkCommandBuffer cmd, uint32_t slot, uint64_t frameIndex);

    Device& device() const { return mDevice; }
    VkCommandBuffer cmd() const { return mCmd; }
    RenderTarget& target() const { return mTarget; }
    uint32_t slot() const { return mSlot; }
    uint64_t frameIndex() const { return mFrameIndex; }

    /// Reserves `bytes` of per-frame uniform memory (aligned for UBO use).
    UniformSlice allocateUniform(size_t bytes);
    /// Copies `value` into a fresh uniform slice.
    template <class T>
    UniformSlice pushUniform(const T& value) {
        UniformSlice slice = allocateUniform(sizeof(T));
        std::memcpy(slice.data, &value, sizeof(T));
        return slice;
    }

    /// Marks a pass for the profiler and RenderDoc (see GpuProfiler::beginPass).
    void beginPass(const char* name);
    void endPass();

private:
    Device& mDevice;
    GpuProfiler& mProfiler;
    RenderTarget& mTarget;
    Buffer& mUniformRing;
    VkCommandBuffer mCmd;
    uint32_t mSlot;
    uint64_t mFrameIndex;
    VkDeviceSize mUniformOffset = 0;
};

/// RAII pass marker: `PassScope pass(frame, "terrain.lowres");`
class PassScope {
public:
    PassScope(FrameContext& frame, const char* name) : mFrame(frame) { mFrame.beginPass(name); }
    ~PassScope() { mFrame.endPass(); }
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;

private:
    FrameContext& mFrame;
};

} // namespace tessera::gpu
