#pragma once
// NullCrowd.h: the null backend's crowd, the CPU reference of every GPU
// backend's culling and binning: the shared per-instance rule (tsLodUpdate,
// CrowdLod.h) over the frame's instances against a state per id, the
// per-tier lists, and the triangles each tier would draw.

#include "tessera/backend/CrowdDesc.h"
#include "tessera/core/Result.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tessera::backends {

class NullCrowd {
public:
    /// What one creature's tiers cost.
    struct Creature {
        uint32_t cageTriangles = 0;
        uint32_t middleTriangles = 0;
        uint32_t farTriangles = 0;
        float levelPerPixel = 0.01f;
    };

    NullCrowd(std::vector<Creature> creatures, uint32_t clips, uint32_t maxInstances, uint32_t maxIds);

    /// Selects and counts one frame; returns the counts per tier.
    backend::CrowdTierCounts draw(const backend::CrowdDrawInfo& draw);
    /// The last frame's lists.
    const backend::CrowdTiers& tiers() const { return mTiers; }

private:
    std::vector<Creature> mCreatures;
    uint32_t mClips = 0;
    uint32_t mMaxInstances = 0;
    std::vector<uint32_t> mState;
    backend::CrowdTiers mTiers;
};

} // namespace tessera::backends
