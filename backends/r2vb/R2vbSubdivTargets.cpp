#include "R2vbSubdivTargets.h"

#include "tessera/shaders/TessPattern.h"

#include <algorithm>
#include <string>

namespace tessera::backends {

namespace {

constexpr VkDeviceSize kVec4Bytes = 16;
/// Widest points target: wide enough that a large surface stays well inside
/// the height limit, narrow enough for every device (4096 is Vulkan's
/// guaranteed maxImageDimension2D).
constexpr uint32_t kPointsWidth = 4096;

} // namespace

Result<std::unique_ptr<R2vbSubdivTargets>> R2vbSubdivTargets::create(gpu::Device& device, const GpuSubdiv& surface) {
    const uint32_t limit = device.properties().limits.maxImageDimension2D;
    const uint32_t points = std::max(surface.refinedPointCount(), 1u);
    const uint32_t width = std::min(std::min(kPointsWidth, limit), points);
    const uint64_t pointRows = (uint64_t(points) + width - 1) / width;
    const uint64_t recordRows = (uint64_t(std::max(surface.domainCount(), 1u)) + R2VB_RECORD_WIDTH - 1) /
                                R2VB_RECORD_WIDTH;
    if (pointRows > limit || recordRows > limit)
        return fail("createSubdiv: r2vb renders ", surface.name(), "'s ",
                    std::to_string(pointRows > limit ? points : surface.domainCount()),
                    pointRows > limit ? " refined points" : " domains", " into a target of ",
                    std::to_string(std::max(pointRows, recordRows)),
                    " rows, more than this device's maxImageDimension2D (", std::to_string(limit), ")");

    // Records come in whole rows, two texels each (EmulatedDrawSource.h).
    const uint64_t recordTexels = 2 * recordRows * R2VB_RECORD_WIDTH;
    if (recordTexels > device.properties().limits.maxTexelBufferElements)
        return fail("createSubdiv: r2vb's records of ", surface.name(), " need ", std::to_string(recordTexels),
                    " texels, more than this device's maxTexelBufferElements (",
                    std::to_string(device.properties().limits.maxTexelBufferElements), ")");

    std::unique_ptr<R2vbSubdivTargets> t(new R2vbSubdivTargets());
    const std::string base = "r2vb.subdiv." + surface.name();
    auto target = [&](uint32_t w, uint32_t h, VkFormat format, const std::string& name) {
        gpu::ImageDesc desc;
        desc.width = w;
        desc.height = h;
        desc.format = format;
        // Rendered to, then copied to a buffer (R2VB); never sampled.
        desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        desc.name = base + "." + name;
        t->mBytes += VkDeviceSize(w) * h * kVec4Bytes;
        return gpu::Image(device, desc);
    };
    t->mPointRows = uint32_t(pointRows);
    t->mPoints = target(width, t->mPointRows, VK_FORMAT_R32G32B32A32_SFLOAT, "points");

    t->mRecordRows = uint32_t(recordRows);
    const char* names[R2VB_COMMAND_TARGETS] = {"recordOuter", "recordInner", "command0", "command1",
                                               "command2",    "command3",    "command4"};
    for (uint32_t i = 0; i < R2VB_COMMAND_TARGETS; ++i)
        t->mRecordTargets[i] = target(R2VB_RECORD_WIDTH, t->mRecordRows,
                                      i < 2 ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R32G32B32A32_UINT, names[i]);
    const VkDeviceSize capacity = t->capacity();
    t->mRecords = gpu::Buffer(device, 2 * capacity * kVec4Bytes,
                              VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                              gpu::MemoryUsage::GpuOnly, base + ".records");
    t->mRecordView = gpu::BufferView(device, t->mRecords, VK_FORMAT_R32G32B32A32_SFLOAT, 0, VK_WHOLE_SIZE,
                                     base + ".records.texels");
    t->mCommands = gpu::Buffer(device, TS_EMU_PIECES * capacity * sizeof(VkDrawIndirectCommand),
                               VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                               gpu::MemoryUsage::GpuOnly, base + ".commands");
    t->mBytes += t->mRecords.size() + t->mCommands.size();
    return t;
}

} // namespace tessera::backends
