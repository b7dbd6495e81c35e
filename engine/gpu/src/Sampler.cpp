#include "tessera/gpu/Sampler.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <utility>

namespace tessera::gpu {

Sampler::Sampler(Device& device, VkFilter filter, VkSamplerAddressMode address, std::string name)
    : Sampler(device, filter,
              filter == VK_FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST, address,
              std::move(name)) {}

Sampler::Sampler(Device& device, VkFilter filter, VkSamplerMipmapMode mipmap, VkSamplerAddressMode address,
                 std::string name) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = filter;
    info.minFilter = filter;
    info.mipmapMode = mipmap;
    info.addressModeU = info.addressModeV = info.addressModeW = address;
    info.maxLod = VK_LOD_CLAMP_NONE;
    VkSampler sampler = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateSampler(device.handle(), &info, nullptr, &sampler));
    mSampler = {device, sampler, name};
}

Sampler::Sampler(Device& device, VkFilter filter, VkCompareOp compare, std::string name) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = filter;
    info.minFilter = filter;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    info.compareEnable = VK_TRUE;
    info.compareOp = compare;
    info.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateSampler(device.handle(), &info, nullptr, &sampler));
    mSampler = {device, sampler, name};
}

} // namespace tessera::gpu
