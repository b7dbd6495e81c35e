#include "tessera/gpu/ComputePipeline.h"

#include "ShaderModule.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/VulkanCheck.h"

#include <utility>

namespace tessera::gpu {

ComputePipeline::ComputePipeline(Device& device, const PipelineLayout& layout, std::span<const uint32_t> spirv,
                                 std::string name)
    : mDevice(&device) {
    ShaderModule module(device, spirv, name + ".shader");
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.handle();
    info.stage.pName = "main";
    info.layout = layout.handle();
    TESSERA_VK_CHECK(vkCreateComputePipelines(device.handle(), VK_NULL_HANDLE, 1, &info, nullptr, &mPipeline));
    device.setName(VK_OBJECT_TYPE_PIPELINE, mPipeline, name);
}

ComputePipeline::~ComputePipeline() {
    if (mDevice) {
        mDevice->clearName(VK_OBJECT_TYPE_PIPELINE, mPipeline);
        vkDestroyPipeline(mDevice->handle(), mPipeline, nullptr);
    }
}

ComputePipeline::ComputePipeline(ComputePipeline&& other) noexcept { *this = std::move(other); }

ComputePipeline& ComputePipeline::operator=(ComputePipeline&& other) noexcept {
    if (this != &other) {
        if (mDevice) {
            mDevice->clearName(VK_OBJECT_TYPE_PIPELINE, mPipeline);
            vkDestroyPipeline(mDevice->handle(), mPipeline, nullptr);
        }
        mDevice = std::exchange(other.mDevice, nullptr);
        mPipeline = std::exchange(other.mPipeline, VK_NULL_HANDLE);
    }
    return *this;
}

} // namespace tessera::gpu
