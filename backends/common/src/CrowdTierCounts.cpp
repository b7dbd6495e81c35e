#include "common/CrowdTierCounts.h"

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Readback.h"

#include <algorithm>
#include <cstring>
#include <vector>

namespace tessera::backends {
namespace {

uint32_t listCount(const uint32_t* args, uint32_t tier, uint32_t creature) {
    return args[(tier * TS_CROWD_MAX_CHARACTERS + creature) * TS_CROWD_ARG_DRAW_WORDS + 1];
}

} // namespace

void reportCrowdCounts(GpuCrowd& crowd, uint32_t slot, backend::FrameReport& report) {
    if (!crowd.argsWritten(slot)) return;
    const auto* args = static_cast<const uint32_t*>(crowd.argsReadback(slot).mapped());
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
        for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
            const uint32_t n = listCount(args, tier, c);
            const GpuCrowd::Creature& k = crowd.creatures()[c];
            report.crowdInstances[tier] += n;
            report.crowdTriangles[tier] += uint64_t(n) * k.tierTriangles(tier);
        }
}

void recordCrowdCountsCopy(VkCommandBuffer cmd, GpuCrowd& crowd, uint32_t slot) {
    const VkBufferCopy copy{0, 0, TS_CROWD_ARG_WORDS * sizeof(uint32_t)};
    vkCmdCopyBuffer(cmd, crowd.args().handle(), crowd.argsReadback(slot).handle(), 1, &copy);
    crowd.setArgsWritten(slot);
}

backend::CrowdTiers readCrowdTiers(gpu::Device& device, GpuCrowd& crowd) {
    const VkDeviceSize listBytes = crowd.lists().size();
    const VkDeviceSize argBytes = TS_CROWD_ARG_WORDS * sizeof(uint32_t);
    const std::vector<std::byte> bytes =
        gpu::readBack(device, listBytes + argBytes, "crowd.tierReadback", "crowd.readTiers",
                      [&](VkCommandBuffer cmd, const gpu::Buffer& readback) {
                          const VkBufferCopy lists{0, 0, listBytes};
                          const VkBufferCopy args{0, listBytes, argBytes};
                          vkCmdCopyBuffer(cmd, crowd.lists().handle(), readback.handle(), 1, &lists);
                          vkCmdCopyBuffer(cmd, crowd.args().handle(), readback.handle(), 1, &args);
                      });
    std::vector<uint32_t> args(TS_CROWD_ARG_WORDS);
    std::memcpy(args.data(), bytes.data() + listBytes, argBytes);
    std::vector<shader::CrowdListEntry> entries(listBytes / sizeof(shader::CrowdListEntry));
    std::memcpy(entries.data(), bytes.data(), entries.size() * sizeof(shader::CrowdListEntry));
    backend::CrowdTiers tiers;
    const uint32_t creatures = uint32_t(crowd.creatures().size());
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
        for (uint32_t c = 0; c < creatures; ++c) {
            const uint32_t n = std::min(listCount(args.data(), tier, c), crowd.maxInstances());
            const uint32_t base = crowd.listBase(crowd.lastSlot(), tier, c);
            for (uint32_t k = 0; k < n; ++k) tiers.instances[tier].push_back(entries[base + k].instance);
        }
    return crowd.toHostIndices(std::move(tiers));
}

} // namespace tessera::backends
