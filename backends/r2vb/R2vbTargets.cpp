#include "R2vbTargets.h"

#include "tessera/shaders/TessPattern.h"

#include <string>

namespace tessera::backends {

namespace {

constexpr VkDeviceSize kVec4Bytes = 16;

} // namespace

uint32_t R2vbTargets::cageRows(uint32_t patches) {
    return (4u * patches + R2VB_CAGE_WIDTH - 1u) / R2VB_CAGE_WIDTH;
}

uint32_t R2vbTargets::recordRows(uint32_t patches) {
    return (patches + R2VB_RECORD_WIDTH - 1u) / R2VB_RECORD_WIDTH;
}

R2vbTargets::R2vbTargets(gpu::Device& device, uint32_t patchCount, uint32_t slot) : mPatchCapacity(patchCount) {
    const std::string suffix = std::to_string(slot);
    auto target = [&](uint32_t width, uint32_t height, VkFormat format, VkDeviceSize texelBytes,
                      VkImageUsageFlags usage, const std::string& name) {
        gpu::ImageDesc desc;
        desc.width = width;
        desc.height = height;
        desc.format = format;
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | usage;
        desc.name = "r2vb." + name + suffix;
        mBytes += VkDeviceSize(width) * height * texelBytes;
        return gpu::Image(device, desc);
    };
    auto buffer = [&](VkDeviceSize size, VkBufferUsageFlags usage, const std::string& name) {
        mBytes += size;
        return gpu::Buffer(device, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT | usage, gpu::MemoryUsage::GpuOnly,
                           "r2vb." + name + suffix);
    };

    // The cage is only sampled; the factors go to a buffer (R2VB).
    const uint32_t cageRowCount = cageRows(patchCount);
    mCage =
        target(R2VB_CAGE_WIDTH, cageRowCount, VK_FORMAT_R32G32B32A32_SFLOAT, 16, VK_IMAGE_USAGE_SAMPLED_BIT, "cage");
    mFactors =
        target(R2VB_CAGE_WIDTH, cageRowCount, VK_FORMAT_R32_SFLOAT, 4, VK_IMAGE_USAGE_TRANSFER_SRC_BIT, "factors");
    mFactorStream = buffer(VkDeviceSize(R2VB_CAGE_WIDTH) * cageRowCount * sizeof(float),
                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "factorStream");

    const uint32_t recordRowCount = recordRows(patchCount);
    const uint32_t recordCapacity = recordRowCount * R2VB_RECORD_WIDTH;
    const char* names[R2VB_COMMAND_TARGETS] = {"recordOuter", "recordInner", "command0", "command1",
                                               "command2",    "command3",    "command4"};
    for (uint32_t i = 0; i < R2VB_COMMAND_TARGETS; ++i) {
        const VkFormat format = i < kFirstCommandTarget ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R32G32B32A32_UINT;
        mRecordTargets[i] =
            target(R2VB_RECORD_WIDTH, recordRowCount, format, kVec4Bytes, VK_IMAGE_USAGE_TRANSFER_SRC_BIT, names[i]);
    }
    mRecords = buffer(2 * recordCapacity * kVec4Bytes, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT, "records");
    // One view over the whole buffer serves every frame's capacity: the
    // contract needs 2 * capacity texels, and capacity never exceeds the buffer's.
    mRecordView =
        gpu::BufferView(device, mRecords, VK_FORMAT_R32G32B32A32_SFLOAT, 0, VK_WHOLE_SIZE, "r2vb.recordView" + suffix);
    mCommands = buffer(TS_EMU_PIECES * recordCapacity * sizeof(VkDrawIndirectCommand),
                       VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "commands");
}

} // namespace tessera::backends
