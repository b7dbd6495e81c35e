#pragma once
/// @file CrowdTierCounts.h
/// What every technique's culling and binning leaves in a GpuCrowd, read the
/// same way on every backend: the tier lists and, in the indirect commands,
/// each list's instance count. Per frame the counts are copied into the
/// frame slot's readback buffer and read when the slot comes round again
/// (FrameReport's crowd counts, no waiting); readCrowdTiers reads the lists
/// themselves, blocking.

#include "common/GpuCrowd.h"
#include "tessera/backend/CrowdDesc.h"
#include "tessera/backend/FrameReport.h"
#include "tessera/gpu/Device.h"

#include <cstdint>

namespace tessera::backends {

/// Adds to `report` the tier counts the GPU wrote the last time frame slot
/// `slot` drew `crowd` (its fence has signalled since).
void reportCrowdCounts(GpuCrowd& crowd, uint32_t slot, backend::FrameReport& report);

/// Records the copy of this frame's counts into the slot's readback buffer,
/// for the slot's next turn (outside any render pass, after the counts are
/// final).
void recordCrowdCountsCopy(VkCommandBuffer cmd, GpuCrowd& crowd, uint32_t slot);

/// Blocking (gpu::readBack): the instances, as the host's indices, that the
/// last drawn frame put in each tier.
backend::CrowdTiers readCrowdTiers(gpu::Device& device, GpuCrowd& crowd);

} // namespace tessera::backends
