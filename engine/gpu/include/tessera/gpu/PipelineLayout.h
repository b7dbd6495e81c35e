#pragma once
/// @file PipelineLayout.h
/// A pipeline layout with one push-descriptor set and optional push constants.
///
/// Tessera binds resources with VK_KHR_push_descriptor: each draw pushes the
/// few buffers and images it reads, so there are no descriptor pools, sets or
/// lifetimes to manage. It plays the role of Granite's automatic descriptor
/// management at a fraction of the code, and every Tessera device has it.

#include "tessera/gpu/UniqueHandle.h"

#include <vulkan/vulkan.h>

#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace tessera::gpu {

class Device;

struct BindingDesc {
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    VkShaderStageFlags stages = VK_SHADER_STAGE_ALL_GRAPHICS;
};

class PipelineLayout {
public:
    PipelineLayout() = default;
    PipelineLayout(Device& device, std::span<const BindingDesc> bindings, uint32_t pushConstantBytes,
                   VkShaderStageFlags pushConstantStages, std::string name);
    PipelineLayout(Device& device, std::initializer_list<BindingDesc> bindings, uint32_t pushConstantBytes,
                   VkShaderStageFlags pushConstantStages, std::string name)
        : PipelineLayout(device, std::span<const BindingDesc>(bindings.begin(), bindings.size()), pushConstantBytes,
                         pushConstantStages, std::move(name)) {}

    VkPipelineLayout handle() const { return mLayout.get(); }
    VkDescriptorSetLayout setLayout() const { return mSetLayout.get(); }
    VkShaderStageFlags pushConstantStages() const { return mPushStages; }

private:
    // The destructor releases the pipeline layout first, then its set
    // layout; a move assignment replaces them the other way round, which
    // Vulkan allows as well (a set layout may go once a layout is made).
    UniqueHandle<VkDescriptorSetLayout, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT> mSetLayout;
    UniqueHandle<VkPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT> mLayout;
    VkShaderStageFlags mPushStages = 0;
};

} // namespace tessera::gpu
