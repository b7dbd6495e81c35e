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
    /// Linear or nearest filtering with the given addressing on all axes;
    /// linear filtering blends between mips too (trilinear).
    Sampler(Device& device, VkFilter filter, VkSamplerAddressMode address, std::string name);
    /// As above, with the filtering between mips given: `mipmap` NEAREST
    /// with a LINEAR `filter` is bilinear within the nearest mip, half the
    /// texel reads of trilinear (what a CPU rasterizer pays for).
    Sampler(Device& device, VkFilter filter, VkSamplerMipmapMode mipmap, VkSamplerAddressMode address,
            std::string name);
    /// A depth-comparison sampler for shadow maps: returns `reference
    /// compare stored` (1 lit, 0 shadowed), filtered bilinearly with
    /// VK_FILTER_LINEAR (hardware 2x2 percentage-closer filtering); outside
    /// the map it clamps to an opaque white border (depth 1: lit).
    Sampler(Device& device, VkFilter filter, VkCompareOp compare, std::string name);

    VkSampler handle() const { return mSampler.get(); }

private:
    UniqueHandle<VkSampler, VK_OBJECT_TYPE_SAMPLER> mSampler;
};

} // namespace tessera::gpu
