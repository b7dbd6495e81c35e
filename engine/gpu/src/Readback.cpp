#include "tessera/gpu/Readback.h"

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"

#include <cstring>

namespace tessera::gpu {

std::vector<std::byte> readBack(Device& device, VkDeviceSize bytes, const std::string& name, const char* label,
                                const std::function<void(VkCommandBuffer cmd, const Buffer& destination)>& record) {
    // Idle first: the last frame's writes are then complete and visible, and
    // the retired slots' deferred releases have run before this allocates.
    device.waitIdle();
    Buffer destination(device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::GpuToCpu, name);
    device.submitImmediate([&](VkCommandBuffer cmd) { record(cmd, destination); }, label);
    std::vector<std::byte> data(bytes);
    std::memcpy(data.data(), destination.mapped(), bytes);
    return data;
}

} // namespace tessera::gpu
