#include "tessera/gpu/ComputePipeline.h"

#include "ShaderModule.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/PipelineLayout.h"
#include "tessera/gpu/VulkanCheck.h"

namespace tessera::gpu {

ComputePipeline::ComputePipeline(Device& device, const PipelineLayout& layout, std::span<const uint32_t> spirv,
                                 std::string name) {
    ShaderModule module(device, spirv, name + ".shader");
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module.handle();
    info.stage.pName = "main";
    info.layout = layout.handle();
    VkPipeline pipeline = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateComputePipelines(device.handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    mPipeline = {device, pipeline, name};
}

} // namespace tessera::gpu
