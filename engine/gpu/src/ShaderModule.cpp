#include "ShaderModule.h"

#include "tessera/gpu/VulkanCheck.h"

#include <utility>

namespace tessera::gpu {

ShaderModule::ShaderModule(Device& device, std::span<const uint32_t> spirv, const std::string& name) : mDevice(&device) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    TESSERA_VK_CHECK(vkCreateShaderModule(device.handle(), &info, nullptr, &mModule));
    device.setName(VK_OBJECT_TYPE_SHADER_MODULE, mModule, name);
}

ShaderModule::~ShaderModule() {
    if (mModule) {
        mDevice->clearName(VK_OBJECT_TYPE_SHADER_MODULE, mModule);
        vkDestroyShaderModule(mDevice->handle(), mModule, nullptr);
    }
}

ShaderModule::ShaderModule(ShaderModule&& other) noexcept
    : mDevice(other.mDevice), mModule(std::exchange(other.mModule, VK_NULL_HANDLE)) {}

} // namespace tessera::gpu
