#include "StreamoutBuffers.h"

#include "tessera/shaders/TessPattern.h"

#include <memory>
#include <string>
#include <utility>

namespace tessera::backends {

namespace {

constexpr VkDeviceSize kTexel = 4 * sizeof(float); // one RGBA32F texel

} // namespace

StreamoutBuffers::Slot& StreamoutBuffers::prepare(uint32_t slot, uint32_t patchesPerSide) {
    Slot& buffers = mSlots[slot];
    if (buffers.capacity < patchesPerSide * patchesPerSide ||
        buffers.gridVertices < (patchesPerSide + 1) * (patchesPerSide + 1)) {
        // A draw of another terrain earlier in this frame may still read the
        // old buffers: free them once the frame retires.
        if (buffers.cage.valid()) mDevice->deferRelease(std::move(buffers));
        buffers = Slot{};
        create(buffers, slot, patchesPerSide);
    }
    return buffers;
}

void StreamoutBuffers::create(Slot& b, uint32_t slotIndex, uint32_t patchesPerSide) {
    const std::string suffix = std::to_string(slotIndex);
    b.gridVertices = (patchesPerSide + 1) * (patchesPerSide + 1);
    b.capacity = patchesPerSide * patchesPerSide;
    const VkBufferUsageFlags xfb = VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT;
    gpu::Device& device = *mDevice;

    b.cage = gpu::Buffer(device, b.gridVertices * kTexel, xfb | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                         gpu::MemoryUsage::GpuOnly, "streamout.cage" + suffix);
    b.cageView =
        gpu::BufferView(device, b.cage, VK_FORMAT_R32G32B32A32_SFLOAT, 0, VK_WHOLE_SIZE, "streamout.cageView" + suffix);
    b.survivors = gpu::Buffer(device, b.capacity * sizeof(uint32_t), xfb | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                              gpu::MemoryUsage::GpuOnly, "streamout.survivors" + suffix);
    // Draw-auto reads the counter as indirect data.
    b.counter =
        gpu::Buffer(device, sizeof(uint32_t),
                    VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_COUNTER_BUFFER_BIT_EXT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                    gpu::MemoryUsage::GpuOnly, "streamout.survivorCount" + suffix);
    b.records = gpu::Buffer(device, 2 * b.capacity * kTexel, xfb | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                            gpu::MemoryUsage::GpuOnly, "streamout.records" + suffix);
    b.recordsView = gpu::BufferView(device, b.records, VK_FORMAT_R32G32B32A32_SFLOAT, 0, VK_WHOLE_SIZE,
                                    "streamout.recordsView" + suffix);
    // Cleared every frame so the commands past the survivors draw nothing.
    b.commands = gpu::Buffer(device, VkDeviceSize(b.capacity) * TS_EMU_PIECES * sizeof(VkDrawIndirectCommand),
                             xfb | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             gpu::MemoryUsage::GpuOnly, "streamout.commands" + suffix);
}

uint64_t StreamoutBuffers::bytes() const {
    uint64_t total = 0;
    for (const Slot& b : mSlots)
        total += b.cage.size() + b.survivors.size() + b.counter.size() + b.records.size() + b.commands.size();
    return total;
}

} // namespace tessera::backends
