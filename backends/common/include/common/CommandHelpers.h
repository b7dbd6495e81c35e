#pragma once
/// @file CommandHelpers.h
/// Small recording helpers every GPU backend's passes share: push-descriptor
/// writes of one resource. (Barriers come from the shared layer, Barriers.h.)

#include <vulkan/vulkan.h>

#include <cstdint>

namespace tessera::backends {

/// A push-descriptor write of one buffer.
VkWriteDescriptorSet bufferWrite(uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* info);
/// A push-descriptor write of one uniform texel buffer view.
VkWriteDescriptorSet texelWrite(uint32_t binding, const VkBufferView* view);
/// A push-descriptor write of one combined image sampler.
VkWriteDescriptorSet imageWrite(uint32_t binding, const VkDescriptorImageInfo* info);

} // namespace tessera::backends
