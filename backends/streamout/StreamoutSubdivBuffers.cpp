#include "StreamoutSubdivBuffers.h"

#include "tessera/shaders/TessPattern.h"

#include <string>

namespace tessera::backends {

StreamoutSubdivBuffers::StreamoutSubdivBuffers(gpu::Device& device, const GpuSubdiv& surface)
    : capacity(surface.domainCount()) {
    const std::string base = "streamout.subdiv." + surface.name();
    const VkBufferUsageFlags xfb = VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT;
    const VkDeviceSize texel = 4 * sizeof(float);
    records = gpu::Buffer(device, 2 * VkDeviceSize(capacity) * texel, xfb | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                          gpu::MemoryUsage::GpuOnly, base + ".records");
    recordsView = gpu::BufferView(device, records, VK_FORMAT_R32G32B32A32_SFLOAT, 0, VK_WHOLE_SIZE,
                                  base + ".records.texels");
    commands = gpu::Buffer(device, VkDeviceSize(capacity) * TS_EMU_PIECES * sizeof(VkDrawIndirectCommand),
                           xfb | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, gpu::MemoryUsage::GpuOnly, base + ".commands");
}

} // namespace tessera::backends
