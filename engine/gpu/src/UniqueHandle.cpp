#include "tessera/gpu/UniqueHandle.h"

#include "tessera/gpu/Device.h"

#include <cassert>

namespace tessera::gpu::detail {
namespace {

template <class VkT>
VkT fromBits(uint64_t bits) {
    if constexpr (std::is_pointer_v<VkT>)
        return reinterpret_cast<VkT>(bits);
    else
        return VkT(bits);
}

} // namespace

void nameHandle(const Device& device, VkObjectType type, uint64_t handle, const std::string& name) {
    device.setName(type, handle, name);
}

void destroyHandle(Device& device, VkObjectType type, uint64_t handle) {
    if (type == VK_OBJECT_TYPE_DEVICE_MEMORY) {
        // Device::free clears the name itself and keeps the memory count.
        device.free(fromBits<VkDeviceMemory>(handle));
        return;
    }
    device.clearName(type, handle);
    const VkDevice d = device.handle();
    switch (type) {
    case VK_OBJECT_TYPE_BUFFER: vkDestroyBuffer(d, fromBits<VkBuffer>(handle), nullptr); break;
    case VK_OBJECT_TYPE_BUFFER_VIEW: vkDestroyBufferView(d, fromBits<VkBufferView>(handle), nullptr); break;
    case VK_OBJECT_TYPE_IMAGE: vkDestroyImage(d, fromBits<VkImage>(handle), nullptr); break;
    case VK_OBJECT_TYPE_IMAGE_VIEW: vkDestroyImageView(d, fromBits<VkImageView>(handle), nullptr); break;
    case VK_OBJECT_TYPE_SAMPLER: vkDestroySampler(d, fromBits<VkSampler>(handle), nullptr); break;
    case VK_OBJECT_TYPE_PIPELINE: vkDestroyPipeline(d, fromBits<VkPipeline>(handle), nullptr); break;
    case VK_OBJECT_TYPE_PIPELINE_LAYOUT:
        vkDestroyPipelineLayout(d, fromBits<VkPipelineLayout>(handle), nullptr);
        break;
    case VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT:
        vkDestroyDescriptorSetLayout(d, fromBits<VkDescriptorSetLayout>(handle), nullptr);
        break;
    case VK_OBJECT_TYPE_SHADER_MODULE: vkDestroyShaderModule(d, fromBits<VkShaderModule>(handle), nullptr); break;
    case VK_OBJECT_TYPE_QUERY_POOL: vkDestroyQueryPool(d, fromBits<VkQueryPool>(handle), nullptr); break;
    default: assert(!"UniqueHandle: no destroy call for this object type"); break;
    }
}

} // namespace tessera::gpu::detail
