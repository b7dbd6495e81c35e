#include "tessera/gpu/Sampler.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <utility>

namespace tessera::gpu {

Sampler::Sampler(Device& device, VkFilter filter, VkSamplerAddressMode address, std::string name) : mDevice(&device) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = filter;
    info.minFilter = filter;
    info.mipmapMode = filter == VK_FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = address;
    info.maxLod = VK_LOD_CLAMP_NONE;
    TESSERA_VK_CHECK(vkCreateSampler(device.handle(), &info, nullptr, &mSampler));
    device.setName(VK_OBJECT_TYPE_SAMPLER, mSampler, name);
}

Sampler::~Sampler() {
    if (mDevice) {
        mDevice->clearName(VK_OBJECT_TYPE_SAMPLER, mSampler);
        vkDestroySampler(mDevice->handle(), mSampler, nullptr);
    }
}

Sampler::Sampler(Sampler&& other) noexcept { *this = std::move(other); }

Sampler& Sampler::operator=(Sampler&& other) noexcept {
    if (this != &other) {
        if (mDevice) {
            mDevice->clearName(VK_OBJECT_TYPE_SAMPLER, mSampler);
            vkDestroySampler(mDevice->handle(), mSampler, nullptr);
        }
        mDevice = std::exchange(other.mDevice, nullptr);
        mSampler = std::exchange(other.mSampler, VK_NULL_HANDLE);
    }
    return *this;
}

} // namespace tessera::gpu
