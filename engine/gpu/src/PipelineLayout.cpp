#include "tessera/gpu/PipelineLayout.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

namespace tessera::gpu {

PipelineLayout::PipelineLayout(Device& device, std::span<const BindingDesc> bindings, uint32_t pushConstantBytes,
                               VkShaderStageFlags pushConstantStages, std::string name)
    : mPushStages(pushConstantStages) {
    std::vector<VkDescriptorSetLayoutBinding> vkBindings;
    for (const auto& b : bindings) vkBindings.push_back({b.binding, b.type, 1, b.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    setInfo.bindingCount = static_cast<uint32_t>(vkBindings.size());
    setInfo.pBindings = vkBindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateDescriptorSetLayout(device.handle(), &setInfo, nullptr, &setLayout));
    mSetLayout = {device, setLayout, name + ".setLayout"};

    VkPushConstantRange range{pushConstantStages, 0, pushConstantBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &setLayout;
    info.pushConstantRangeCount = pushConstantBytes ? 1 : 0;
    info.pPushConstantRanges = &range;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreatePipelineLayout(device.handle(), &info, nullptr, &layout));
    mLayout = {device, layout, name};
}

} // namespace tessera::gpu
