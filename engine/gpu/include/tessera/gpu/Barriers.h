#pragma once
/// @file Barriers.h
/// Synchronization2 barriers: every pass states the stages and accesses it
/// waits for and the ones it makes ready. The one place, with
/// transitionImage (Image.h), that records vkCmdPipelineBarrier2; the host,
/// the backends and the GPU tests all go through it.
///
/// - memoryBarrier: one global memory dependency, recorded at once.
/// - imageBarrier and bufferBarrier build a whole-image layout transition and
///   a whole-buffer dependency; pipelineBarrier records any number of them as
///   one barrier, for passes that hand several resources on at once (r2vb's
///   render targets and the buffers they are copied into).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

namespace tessera::gpu {

class Buffer;
class Image;

/// Records one global memory barrier: writes by `srcAccess` in `srcStages`
/// become visible to `dstAccess` in `dstStages`.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);

/// A layout transition of `image` (its aspect, the first `mipLevels` levels,
/// every array layer, no queue-family transfer) to record with pipelineBarrier().
VkImageMemoryBarrier2 imageBarrier(const Image& image, VkImageLayout from, VkImageLayout to,
                                   VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                                   uint32_t mipLevels = 1);

/// A dependency on the whole of `buffer` (no queue-family transfer) to
/// record with pipelineBarrier().
VkBufferMemoryBarrier2 bufferBarrier(const Buffer& buffer, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                     VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

/// Records one vkCmdPipelineBarrier2 with all of `images` and `buffers`.
void pipelineBarrier(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> images,
                     std::span<const VkBufferMemoryBarrier2> buffers = {});

} // namespace tessera::gpu
