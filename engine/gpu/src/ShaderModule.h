#pragma once
// Internal: a named VkShaderModule that lives while a pipeline is compiled.

#include "tessera/gpu/Device.h"
#include "tessera/gpu/UniqueHandle.h"

#include <cstdint>
#include <span>
#include <string>

namespace tessera::gpu {

class ShaderModule {
public:
    ShaderModule(Device& device, std::span<const uint32_t> spirv, const std::string& name);

    VkShaderModule handle() const { return mModule.get(); }

private:
    UniqueHandle<VkShaderModule, VK_OBJECT_TYPE_SHADER_MODULE> mModule;
};

} // namespace tessera::gpu
