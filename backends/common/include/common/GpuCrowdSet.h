#pragma once
/// @file GpuCrowdSet.h
/// A backend's instanced crowds: the handle table behind createCrowd,
/// destroyCrowd and readCrowdTiers, and the tier counts FrameReport carries,
/// the same for every GPU backend. Each technique's culling and binning
/// writes the same results (GpuCrowd's lists, per-list instance counts in
/// its indirect commands), so reading them back is shared too.

#include "common/GpuCrowd.h"
#include "tessera/backend/CrowdDesc.h"
#include "tessera/backend/FrameReport.h"
#include "tessera/core/Result.h"

#include <functional>
#include <memory>
#include <vector>

namespace tessera::backends {

class GpuCrowdSet {
public:
    GpuCrowdSet() = default;
    explicit GpuCrowdSet(gpu::Device& device) : mDevice(&device) {}

    /// Makes a crowd (GpuCrowd::create) and returns its handle.
    Result<backend::CrowdHandle> create(const backend::CrowdDesc& desc,
                                        const std::function<GpuCharacter*(backend::CharacterHandle)>& find,
                                        VkBufferUsageFlags writeUsage);
    /// Destroys a crowd once the frames that use it have retired.
    void destroy(backend::CrowdHandle handle);
    /// The crowd, or null for an unknown or destroyed handle.
    GpuCrowd* find(backend::CrowdHandle handle);
    /// Destroys every crowd now (shutdown: the device is idle).
    void clear() { mCrowds.clear(); }

    /// Blocking: the instances (host indices) the last drawn frame put in
    /// each tier, from the lists and the counts in the indirect commands.
    Result<backend::CrowdTiers> readTiers(backend::CrowdHandle handle);

    /// Adds to `report` the tier counts the GPU wrote the last time frame
    /// slot `slot` drew `crowd` (its fence has signalled), then records the
    /// copy of this frame's counts for the slot's next turn (outside any
    /// render pass, after the counts are final).
    static void reportCounts(GpuCrowd& crowd, uint32_t slot, backend::FrameReport& report);
    static void recordCountsCopy(VkCommandBuffer cmd, GpuCrowd& crowd, uint32_t slot);

private:
    gpu::Device* mDevice = nullptr;
    std::vector<std::unique_ptr<GpuCrowd>> mCrowds; ///< null once destroyed
};

} // namespace tessera::backends
