#include "ShaderModule.h"

#include "tessera/gpu/VulkanCheck.h"

namespace tessera::gpu {

ShaderModule::ShaderModule(Device& device, std::span<const uint32_t> spirv, const std::string& name) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateShaderModule(device.handle(), &info, nullptr, &module));
    mModule = {device, module, name};
}

} // namespace tessera::gpu
