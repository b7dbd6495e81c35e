#pragma once
/// @file ComputePipeline.h
/// A named compute pipeline from embedded SPIR-V.

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
    ~ComputePipeline();
    ComputePipeline(ComputePipeline&& other) noexcept;
    ComputePipeline& operator=(ComputePipeline&& other) noexcept;
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    VkPipeline handle() const { return mPipeline; }
    bool valid() const { return mPipeline != VK_NULL_HANDLE; }

private:
    Device* mDevice = nullptr;
    VkPipeline mPipeline = VK_NULL_HANDLE;
};

} // namespace tessera::gpu
