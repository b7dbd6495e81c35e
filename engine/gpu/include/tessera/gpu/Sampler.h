#pragma once
/// @file Sampler.h
/// A named VkSampler.

#include "tessera/gpu/UniqueHandle.h"

#include <vulkan/vulkan.h>

#include <string>

namespace tessera::gpu {

class Device;

class Sampler {
public:
    Sampler() = default;
    /// Linear or nearest filtering with the given addressing on all axes.
    Sampler(Device& device, VkFilter filter, VkSamplerAddressMode address, std::string name);

    VkSampler handle() const { return mSampler.get(); }

private:
    UniqueHandle<VkSampler, VK_OBJECT_TYPE_SAMPLER> mSampler;
};

} // namespace tessera::gpu
