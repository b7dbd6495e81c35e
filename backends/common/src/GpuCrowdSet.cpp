#include "common/GpuCrowdSet.h"

#include "tessera/gpu/Barriers.h"
#include "tessera/gpu/Device.h"

#include <algorithm>
#include <cstring>

namespace tessera::backends {
namespace {

uint32_t listCount(const uint32_t* args, uint32_t tier, uint32_t creature) {
    return args[(tier * TS_CROWD_MAX_CHARACTERS + creature) * TS_CROWD_ARG_DRAW_WORDS + 1];
}

} // namespace

Result<backend::CrowdHandle> GpuCrowdSet::create(const backend::CrowdDesc& desc,
                                                 const std::function<GpuCharacter*(backend::CharacterHandle)>& find,
                                                 VkBufferUsageFlags writeUsage) {
    if (!mDevice) return Error{"createCrowd before initialize"};
    auto created = GpuCrowd::create(*mDevice, desc, find, writeUsage);
    if (!created) return created.error();
    mCrowds.push_back(std::move(created.value()));
    return backend::CrowdHandle{static_cast<uint32_t>(mCrowds.size() - 1)};
}

void GpuCrowdSet::destroy(backend::CrowdHandle handle) {
    if (!find(handle)) return;
    GpuCrowd* released = mCrowds[handle.id].release();
    mDevice->deferDestroy([released] { delete released; });
}

GpuCrowd* GpuCrowdSet::find(backend::CrowdHandle handle) {
    return handle.valid() && handle.id < mCrowds.size() ? mCrowds[handle.id].get() : nullptr;
}

Result<backend::CrowdTiers> GpuCrowdSet::readTiers(backend::CrowdHandle handle) {
    GpuCrowd* crowd = find(handle);
    if (!crowd) return Error{"readCrowdTiers: no such crowd"};
    mDevice->waitIdle();
    const VkDeviceSize listBytes = crowd->lists().size();
    const VkDeviceSize argBytes = TS_CROWD_ARG_WORDS * sizeof(uint32_t);
    gpu::Buffer readback(*mDevice, listBytes + argBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUsage::GpuToCpu,
                         "crowd.tierReadback");
    mDevice->submitImmediate(
        [&](VkCommandBuffer cmd) {
            const VkBufferCopy lists{0, 0, listBytes};
            const VkBufferCopy args{0, listBytes, argBytes};
            vkCmdCopyBuffer(cmd, crowd->lists().handle(), readback.handle(), 1, &lists);
            vkCmdCopyBuffer(cmd, crowd->args().handle(), readback.handle(), 1, &args);
        },
        "crowd.readTiers");
    const auto* bytes = static_cast<const uint8_t*>(readback.mapped());
    std::vector<uint32_t> args(TS_CROWD_ARG_WORDS);
    std::memcpy(args.data(), bytes + listBytes, argBytes);
    const auto* entries = reinterpret_cast<const shader::CrowdListEntry*>(bytes);
    backend::CrowdTiers tiers;
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
        for (uint32_t c = 0; c < crowd->creatures().size(); ++c) {
            const uint32_t n = std::min(listCount(args.data(), tier, c), crowd->maxInstances());
            const uint32_t base = shader::tsCrowdListBase(tier, c, uint32_t(crowd->creatures().size()), crowd->maxInstances());
            for (uint32_t k = 0; k < n; ++k) tiers.instances[tier].push_back(entries[base + k].instance);
        }
    return crowd->toHostIndices(std::move(tiers));
}

void GpuCrowdSet::reportCounts(GpuCrowd& crowd, uint32_t slot, backend::FrameReport& report) {
    if (!crowd.argsWritten(slot)) return;
    const auto* args = static_cast<const uint32_t*>(crowd.argsReadback(slot).mapped());
    for (uint32_t tier = 0; tier < TS_LOD_TIERS; ++tier)
        for (uint32_t c = 0; c < crowd.creatures().size(); ++c) {
            const uint32_t n = listCount(args, tier, c);
            const GpuCrowd::Creature& k = crowd.creatures()[c];
            report.crowdInstances[tier] += n;
            report.crowdTriangles[tier] += uint64_t(n) * (tier == TS_LOD_FAR ? k.farTriangles : k.cageTriangles);
        }
}

void GpuCrowdSet::recordCountsCopy(VkCommandBuffer cmd, GpuCrowd& crowd, uint32_t slot) {
    const VkBufferCopy copy{0, 0, TS_CROWD_ARG_WORDS * sizeof(uint32_t)};
    vkCmdCopyBuffer(cmd, crowd.args().handle(), crowd.argsReadback(slot).handle(), 1, &copy);
    crowd.setArgsWritten(slot);
}

} // namespace tessera::backends
