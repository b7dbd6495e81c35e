#include "tessera/gpu/Barriers.h"

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Image.h"

namespace tessera::gpu {
namespace {

VkImageMemoryBarrier2 layoutTransition(VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                                       VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                       VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, uint32_t mipLevels) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, 0, mipLevels, 0, 1};
    return barrier;
}

} // namespace

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStages;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStages;
    barrier.dstAccessMask = dstAccess;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

VkImageMemoryBarrier2 imageBarrier(const Image& image, VkImageLayout from, VkImageLayout to,
                                   VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess, uint32_t mipLevels) {
    VkImageMemoryBarrier2 barrier = layoutTransition(image.handle(), image.aspect(), from, to, srcStage, srcAccess,
                                                     dstStage, dstAccess, mipLevels);
    barrier.subresourceRange.layerCount = image.arrayLayers();
    return barrier;
}

VkBufferMemoryBarrier2 bufferBarrier(const Buffer& buffer, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                     VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkBufferMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.buffer = buffer.handle();
    barrier.offset = 0;
    barrier.size = VK_WHOLE_SIZE;
    return barrier;
}

void pipelineBarrier(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> images,
                     std::span<const VkBufferMemoryBarrier2> buffers) {
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = static_cast<uint32_t>(images.size());
    dependency.pImageMemoryBarriers = images.data();
    dependency.bufferMemoryBarrierCount = static_cast<uint32_t>(buffers.size());
    dependency.pBufferMemoryBarriers = buffers.data();
    vkCmdPipelineBarrier2(cmd, &dependency);
}

// Declared in Image.h; defined here beside its siblings so that one file
// records every barrier.
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                     VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                     VkAccessFlags2 dstAccess, uint32_t mipLevels) {
    const VkImageMemoryBarrier2 barrier =
        layoutTransition(image, aspect, from, to, srcStage, srcAccess, dstStage, dstAccess, mipLevels);
    pipelineBarrier(cmd, {&barrier, 1});
}

} // namespace tessera::gpu
