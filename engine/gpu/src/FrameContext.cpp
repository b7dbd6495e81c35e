#include "tessera/gpu/FrameContext.h"

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/GpuProfiler.h"
#include "tessera/gpu/VulkanCheck.h"

namespace tessera::gpu {

FrameContext::FrameContext(Device& device, GpuProfiler& profiler, RenderTarget& target, Buffer& uniformRing,
                           VkCommandBuffer cmd, uint32_t slot, uint64_t frameIndex)
    : mDevice(device), mProfiler(profiler), mTarget(target), mUniformRing(uniformRing), mCmd(cmd), mSlot(slot),
      mFrameIndex(frameIndex) {}

UniformSlice FrameContext::allocateUniform(size_t bytes) {
    const VkDeviceSize align = mDevice.properties().limits.minUniformBufferOffsetAlignment;
    const VkDeviceSize offset = (mUniformOffset + align - 1) / align * align;
    if (offset + bytes > mUniformRing.size())
        fatalVulkanError("FrameContext::allocateUniform (per-frame uniform ring exhausted)", VK_ERROR_OUT_OF_DEVICE_MEMORY);
    mUniformOffset = offset + bytes;
    return {mUniformRing.handle(), offset, bytes, static_cast<std::byte*>(mUniformRing.mapped()) + offset};
}

void FrameContext::beginPass(const char* name) { mProfiler.beginPass(mCmd, name); }

void FrameContext::endPass() { mProfiler.endPass(mCmd); }

} // namespace tessera::gpu
