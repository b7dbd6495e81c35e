#include "tessera/gpu/PipelineLayout.h"

#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <utility>

namespace tessera::gpu {

PipelineLayout::PipelineLayout(Device& device, std::span<const BindingDesc> bindings, uint32_t pushConstantBytes,
                               VkShaderStageFlags pushConstantStages, std::string name)
    : mDevice(&device), mPushStages(pushConstantStages) {
    std::vector<VkDescriptorSetLayoutBinding> vkBindings;
    for (const auto& b : bindings) vkBindings.push_back({b.binding, b.type, 1, b.stages, nullptr});
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    setInfo.bindingCount = static_cast<uint32_t>(vkBindings.size());
    setInfo.pBindings = vkBindings.data();
    TESSERA_VK_CHECK(vkCreateDescriptorSetLayout(device.handle(), &setInfo, nullptr, &mSetLayout));
    device.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, mSetLayout, name + ".setLayout");

    VkPushConstantRange range{pushConstantStages, 0, pushConstantBytes};
    VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    info.setLayoutCount = 1;
    info.pSetLayouts = &mSetLayout;
    info.pushConstantRangeCount = pushConstantBytes ? 1 : 0;
    info.pPushConstantRanges = &range;
    TESSERA_VK_CHECK(vkCreatePipelineLayout(device.handle(), &info, nullptr, &mLayout));
    device.setName(VK_OBJECT_TYPE_PIPELINE_LAYOUT, mLayout, name);
}

PipelineLayout::~PipelineLayout() {
    if (!mDevice) return;
    mDevice->clearName(VK_OBJECT_TYPE_PIPELINE_LAYOUT, mLayout);
    vkDestroyPipelineLayout(mDevice->handle(), mLayout, nullptr);
    mDevice->clearName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, mSetLayout);
    vkDestroyDescriptorSetLayout(mDevice->handle(), mSetLayout, nullptr);
}

PipelineLayout::PipelineLayout(PipelineLayout&& other) noexcept { *this = std::move(other); }

PipelineLayout& PipelineLayout::operator=(PipelineLayout&& other) noexcept {
    if (this != &other) {
        this->~PipelineLayout();
        mDevice = std::exchange(other.mDevice, nullptr);
        mSetLayout = std::exchange(other.mSetLayout, VK_NULL_HANDLE);
        mLayout = std::exchange(other.mLayout, VK_NULL_HANDLE);
        mPushStages = other.mPushStages;
    }
    return *this;
}

} // namespace tessera::gpu
