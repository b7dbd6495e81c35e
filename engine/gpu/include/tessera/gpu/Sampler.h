#pragma once
/// @file Sampler.h
/// A named VkSampler.

#include <vulkan/vulkan.h>

#include <string>

namespace tessera::gpu {

class Device;

class Sampler {
public:
    Sampler() = default;
    /// Linear or nearest filtering with the given addressing on all axes.
    Sampler(Device& device, VkFilter filter, VkSamplerAddressMode address, std::string name);
    ~Sampler();
    Sampler(Sampler&& other) noexcept;
    Sampler& operator=(Sampler&& other) noexcept;
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;

    VkSampler handle() const { return mSampler; }

private:
    Device* mDevice = nullptr;
    VkSampler mSampler = VK_NULL_HANDLE;
};

} // namespace tessera::gpu
