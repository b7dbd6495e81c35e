#pragma once
/// @file CommandHelpers.h
/// Small recording helpers every GPU backend's passes share: push-descriptor
/// writes of one resource and a global synchronization2 memory barrier.

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tessera::backends {

/// A push-descriptor write of one buffer.
VkWriteDescriptorSet bufferWrite(uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* info);
/// A push-descriptor write of one uniform texel buffer view.
VkWriteDescriptorSet texelWrite(uint32_t binding, const VkBufferView* view);
/// A global memory barrier.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);

} // namespace tessera::backends
