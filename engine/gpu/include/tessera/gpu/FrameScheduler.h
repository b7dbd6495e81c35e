#pragma once
/// @file FrameScheduler.h
/// The host's frame loop on the GPU side: frames in flight, command buffers,
/// fences, submission, query collection and readback.

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/GpuProfiler.h"

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace tessera::profiler {
class Profiler;
}

namespace tessera::gpu {

class Device;
class RenderTarget;
class Swapchain;

class FrameScheduler {
public:
    FrameScheduler(Device& device, profiler::Profiler& profiler, RenderTarget& target);
    ~FrameScheduler();
    FrameScheduler(const FrameScheduler&) = delete;
    FrameScheduler& operator=(const FrameScheduler&) = delete;

    /// Waits for the slot's previous use, resolves its queries into the
    /// profiler, runs deferred deletions and begins its command buffer.
    FrameContext& beginFrame(uint64_t frameIndex);

    /// Ends and submits the frame. With `readback`, the color target is copied
    /// to host memory; fetch it with readbackPixels() after waitIdle(). With a
    /// swapchain, the target is blitted to the acquired image and presented.
    void endFrame(bool readback, Swapchain* swapchain = nullptr);

    /// Waits for every submitted frame and resolves all queries.
    void waitIdle();

    /// RGBA8 pixels of the last frame submitted with readback=true.
    std::vector<uint8_t> readbackPixels() const;

    /// Points subsequent frames at a new target (after a resize); call after waitIdle.
    void setTarget(RenderTarget& target) { mTarget = &target; }

    GpuProfiler& gpuProfiler() { return mGpuProfiler; }

private:
    struct Slot {
        VkCommandPool pool = VK_NULL_HANDLE;
        VkCommandBuffer cmd = VK_NULL_HANDLE;
        VkFence fence = VK_NULL_HANDLE;
        Buffer uniforms;
        bool submitted = false;
    };

    Device& mDevice;
    profiler::Profiler& mProfiler;
    RenderTarget* mTarget;
    GpuProfiler mGpuProfiler;
    std::array<Slot, 2> mSlots;
    uint32_t mCurrent = 0;
    std::optional<FrameContext> mContext;
    Buffer mReadback;
    uint32_t mReadbackWidth = 0;
    uint32_t mReadbackHeight = 0;
};

} // namespace tessera::gpu
