#include "tessera/gpu/FrameScheduler.h"

#include "tessera/gpu/Barriers.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/gpu/Swapchain.h"
#include "tessera/gpu/VulkanCheck.h"
#include "tessera/profiler/Profiler.h"

#include <cstring>
#include <string>

namespace tessera::gpu {
namespace {
constexpr VkDeviceSize kUniformRingBytes = 1u << 20;
}

FrameScheduler::FrameScheduler(Device& device, profiler::Profiler& profiler, RenderTarget& target)
    : mDevice(device), mProfiler(profiler), mTarget(&target), mGpuProfiler(device, profiler, kFramesInFlight) {
    static_assert(kFramesInFlight == 2, "mSlots is sized for two frames in flight");
    // The uniform rings first: they are the allocations that can run out of
    // device memory (OutOfDeviceMemory), and a constructor that throws never
    // runs the destructor, so no pool or fence may exist yet when they do.
    for (uint32_t i = 0; i < mSlots.size(); ++i)
        mSlots[i].uniforms = Buffer(device, kUniformRingBytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                    MemoryUsage::CpuToGpu, "frame" + std::to_string(i) + ".uniformRing");
    for (uint32_t i = 0; i < mSlots.size(); ++i) {
        Slot& s = mSlots[i];
        const std::string prefix = "frame" + std::to_string(i);
        VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        poolInfo.queueFamilyIndex = device.queueFamily();
        TESSERA_VK_CHECK(vkCreateCommandPool(device.handle(), &poolInfo, nullptr, &s.pool));
        device.setName(VK_OBJECT_TYPE_COMMAND_POOL, s.pool, prefix + ".commandPool");
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = s.pool;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        TESSERA_VK_CHECK(vkAllocateCommandBuffers(device.handle(), &alloc, &s.cmd));
        device.setName(VK_OBJECT_TYPE_COMMAND_BUFFER, s.cmd, prefix + ".commandBuffer");
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        TESSERA_VK_CHECK(vkCreateFence(device.handle(), &fenceInfo, nullptr, &s.fence));
        device.setName(VK_OBJECT_TYPE_FENCE, s.fence, prefix + ".fence");
    }
}

FrameScheduler::~FrameScheduler() {
    waitIdle();
    for (auto& s : mSlots) {
        vkDestroyFence(mDevice.handle(), s.fence, nullptr);
        vkDestroyCommandPool(mDevice.handle(), s.pool, nullptr);
    }
}

FrameContext& FrameScheduler::beginFrame(uint64_t frameIndex) {
    mCurrent = static_cast<uint32_t>(frameIndex % mSlots.size());
    Slot& s = mSlots[mCurrent];
    if (s.submitted) {
        TESSERA_VK_CHECK(vkWaitForFences(mDevice.handle(), 1, &s.fence, VK_TRUE, UINT64_MAX));
        TESSERA_VK_CHECK(vkResetFences(mDevice.handle(), 1, &s.fence));
        s.submitted = false;
        mGpuProfiler.collect(mCurrent);
        mDevice.retireSlot(mCurrent);
    }
    mDevice.setCurrentSlot(mCurrent);
    TESSERA_VK_CHECK(vkResetCommandPool(mDevice.handle(), s.pool, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    TESSERA_VK_CHECK(vkBeginCommandBuffer(s.cmd, &begin));
    const std::string label = "frame " + std::to_string(frameIndex);
    mDevice.beginLabel(s.cmd, label.c_str());
    mGpuProfiler.beginFrame(s.cmd, mCurrent, frameIndex);
    mContext.emplace(mDevice, mGpuProfiler, *mTarget, s.uniforms, s.cmd, mCurrent, frameIndex);
    return *mContext;
}

void FrameScheduler::endFrame(bool readback, Swapchain* swapchain) {
    Slot& s = mSlots[mCurrent];
    VkCommandBuffer cmd = s.cmd;
    Image& color = mTarget->color();

    if (readback) {
        const VkDeviceSize bytes = VkDeviceSize(color.width()) * color.height() * 4;
        if (!mReadback.valid() || mReadback.size() < bytes)
            mReadback = Buffer(mDevice, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::GpuToCpu, "readback.color");
        mReadbackWidth = color.width();
        mReadbackHeight = color.height();
        mGpuProfiler.beginPass(cmd, "host.readback");
        transitionImage(cmd, color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, RenderTarget::kColorLayoutAfterPasses,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {color.width(), color.height(), 1};
        vkCmdCopyImageToBuffer(cmd, color.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, mReadback.handle(), 1, &region);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_HOST_READ_BIT);
        // Leave the image as the non-readback path does, so a following blit sees one layout.
        transitionImage(cmd, color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        RenderTarget::kColorLayoutAfterPasses, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_NONE,
                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
        mGpuProfiler.endPass(cmd);
    }

    VkSemaphore acquired = VK_NULL_HANDLE;
    const bool presenting = swapchain && swapchain->acquire(acquired);
    if (presenting) {
        mGpuProfiler.beginPass(cmd, "host.present");
        swapchain->recordPresentBlit(cmd, *mTarget);
        mGpuProfiler.endPass(cmd);
    }
    mDevice.endLabel(cmd);
    TESSERA_VK_CHECK(vkEndCommandBuffer(cmd));

    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = cmd;
    VkSemaphoreSubmitInfo waitInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    waitInfo.semaphore = acquired;
    waitInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    VkSemaphoreSubmitInfo signalInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signalInfo.semaphore = presenting ? swapchain->renderFinished() : VK_NULL_HANDLE;
    signalInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmdInfo;
    if (presenting) {
        submit.waitSemaphoreInfoCount = 1;
        submit.pWaitSemaphoreInfos = &waitInfo;
        submit.signalSemaphoreInfoCount = 1;
        submit.pSignalSemaphoreInfos = &signalInfo;
    }
    mGpuProfiler.markSubmitted(mCurrent, mProfiler.nowNs());
    TESSERA_VK_CHECK(vkQueueSubmit2(mDevice.queue(), 1, &submit, s.fence));
    s.submitted = true;
    mContext.reset();
    if (presenting) swapchain->present();
    mProfiler.recordCounter({"device memory (MiB)", mProfiler.currentFrame(), mProfiler.nowNs(),
                             static_cast<double>(mDevice.allocatedBytes()) / (1024.0 * 1024.0)});
}

void FrameScheduler::waitIdle() {
    for (uint32_t i = 0; i < mSlots.size(); ++i) {
        Slot& s = mSlots[i];
        if (!s.submitted) continue;
        TESSERA_VK_CHECK(vkWaitForFences(mDevice.handle(), 1, &s.fence, VK_TRUE, UINT64_MAX));
        TESSERA_VK_CHECK(vkResetFences(mDevice.handle(), 1, &s.fence));
        s.submitted = false;
        mGpuProfiler.collect(i);
        mDevice.retireSlot(i);
    }
}

std::vector<uint8_t> FrameScheduler::readbackPixels() const {
    if (!mReadback.valid()) return {};
    std::vector<uint8_t> pixels(size_t(mReadbackWidth) * mReadbackHeight * 4);
    std::memcpy(pixels.data(), mReadback.mapped(), pixels.size());
    return pixels;
}

} // namespace tessera::gpu
