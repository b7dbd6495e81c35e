#pragma once
/// @file StreamoutRecording.h
/// Small recording helpers streamout's passes share: the attachment-less
/// rendering scope transform feedback needs, global barriers, and descriptor
/// writes for push descriptors.

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tessera::backends::streamout {

/// Opens rendering with no attachments and sets a 1x1 viewport: transform
/// feedback only exists inside rendering, and these passes rasterise nothing.
void beginStreamOut(VkCommandBuffer cmd);
void endStreamOut(VkCommandBuffer cmd);

/// A global memory barrier (synchronization2).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess);

/// A push-descriptor write of one buffer or one texel-buffer view.
VkWriteDescriptorSet bufferWrite(uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* info);
VkWriteDescriptorSet texelWrite(uint32_t binding, const VkBufferView* view);

} // namespace tessera::backends::streamout
