#include "tessera/gpu/BufferView.h"

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

namespace tessera::gpu {

BufferView::BufferView(Device& device, const Buffer& buffer, VkFormat format, VkDeviceSize offset,
                       VkDeviceSize range, std::string name) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.handle();
    info.format = format;
    info.offset = offset;
    info.range = range;
    VkBufferView view = VK_NULL_HANDLE;
    TESSERA_VK_CHECK(vkCreateBufferView(device.handle(), &info, nullptr, &view));
    mView = {device, view, name};
}

} // namespace tessera::gpu
