#pragma once
/// @file ComputePipeline.h
/// A named compute pipeline from embedded SPIR-V.

#include "tessera/gpu/UniqueHandle.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>

namespace tessera::gpu {

class Device;
class PipelineLayout;

class ComputePipeline {
public:
    ComputePipeline() = default;
    ComputePipeline(Device& device, const PipelineLayout& layout, std::span<const uint32_t> spirv, std::string name);

    VkPipeline handle() const { return mPipeline.get(); }
    bool valid() const { return bool(mPipeline); }

private:
    UniqueHandle<VkPipeline, VK_OBJECT_TYPE_PIPELINE> mPipeline;
};

} // namespace tessera::gpu
