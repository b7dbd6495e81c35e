#pragma once
// Internal: a named VkShaderModule that lives while a pipeline is compiled.

#include "tessera/gpu/Device.h"

#include <cstdint>
#include <span>
#include <string>

namespace tessera::gpu {

class ShaderModule {
public:
    ShaderModule(Device& device, std::span<const uint32_t> spirv, const std::string& name);
    ~ShaderModule();
    ShaderModule(const ShaderModule&) = delete;
    ShaderModule& operator=(const ShaderModule&) = delete;
    ShaderModule(ShaderModule&& other) noexcept;
    ShaderModule& operator=(ShaderModule&&) = delete;

    VkShaderModule handle() const { return mModule; }

private:
    Device* mDevice;
    VkShaderModule mModule = VK_NULL_HANDLE;
};

} // namespace tessera::gpu
