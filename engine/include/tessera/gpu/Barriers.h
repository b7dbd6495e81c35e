#pragma once
/// @file Barriers.h
/// Global synchronization2 memory barriers, the buffer-side counterpart of
/// transitionImage (Image.h): every pass states the stages and accesses it
/// waits for and the ones it makes ready.

#include <vulkan/vulkan.h>

namespace tessera::gpu {

/// Records one global memory barrier: writes by `srcAccess` in `srcStages`
/// become visible to `dstAccess` in `dstStages`.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);

} // namespace tessera::gpu
