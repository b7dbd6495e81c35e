#include "tessera/gpu/BufferView.h"

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/VulkanCheck.h"

#include <utility>

namespace tessera::gpu {

BufferView::BufferView(Device& device, const Buffer& buffer, VkFormat format, VkDeviceSize offset,
                       VkDeviceSize range, std::string name)
    : mDevice(&device) {
    VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = buffer.handle();
    info.format = format;
    info.offset = offset;
    info.range = range;
    TESSERA_VK_CHECK(vkCreateBufferView(device.handle(), &info, nullptr, &mView));
    device.setName(VK_OBJECT_TYPE_BUFFER_VIEW, mView, name);
}

BufferView::~BufferView() {
    if (mDevice) {
        mDevice->clearName(VK_OBJECT_TYPE_BUFFER_VIEW, mView);
        vkDestroyBufferView(mDevice->handle(), mView, nullptr);
    }
}

BufferView::BufferView(BufferView&& other) noexcept { *this = std::move(other); }

BufferView& BufferView::operator=(BufferView&& other) noexcept {
    if (this != &other) {
        if (mDevice) {
            mDevice->clearName(VK_OBJECT_TYPE_BUFFER_VIEW, mView);
            vkDestroyBufferView(mDevice->handle(), mView, nullptr);
        }
        mDevice = std::exchange(other.mDevice, nullptr);
        mView = std::exchange(other.mView, VK_NULL_HANDLE);
    }
    return *this;
}

} // namespace tessera::gpu
