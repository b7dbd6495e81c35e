#pragma once
/// @file LodFrame.h
/// The LOD manager's answer for one frame: the parameters every backend's
/// GPU selection reads, and the CPU reference's per-tier instance lists.

#include "tessera/shaders/CrowdLod.h"

#include <array>
#include <cstdint>
#include <vector>

namespace tessera::lod {

enum class Tier : uint32_t { Near = TS_LOD_NEAR, Middle = TS_LOD_MIDDLE, Far = TS_LOD_FAR, Impostor = TS_LOD_IMPOSTOR };
inline constexpr uint32_t kTierCount = TS_LOD_TIERS;
const char* toString(Tier tier);

/// One instance drawn in one tier.
struct LodDraw {
    uint32_t instance = 0; ///< index into the frame's instances
    /// Tessellation level (near tier; 1 elsewhere).
    float level = 1.0f;
    /// Share of the instance this tier draws, in (0, 1]: 1 unless it
    /// cross-fades, when the two tiers' dither masks split its pixels.
    float coverage = 1.0f;
    /// True for the copy of the tier the instance fades out of (its dither
    /// mask is the complement of the incoming tier's).
    bool fadingOut = false;
};

/// Counts for one tier in one frame.
struct LodTierCount {
    uint32_t instances = 0; ///< draws, fading copies included
    uint32_t fading = 0;    ///< of which cross-fade copies (either side)
    uint64_t triangles = 0; ///< after tessellation (an impostor: its card's two)
};

struct LodFrame {
    /// What the GPU selection reads (the budget's cuts and level cap included).
    shader::CrowdLodParams params{};
    /// The CPU reference's draws per tier, in instance order (left empty
    /// where the manager keeps no lists: LodManager::keepLists).
    std::array<std::vector<LodDraw>, kTierCount> tiers;
    std::array<LodTierCount, kTierCount> counts{};
    uint32_t inView = 0;        ///< instances whose sphere meets the frustum, not behind the terrain
    /// Instances in the frustum that the terrain hides (tsLodBehindTerrain),
    /// by the tier their size would have taken (of those tested: untested).
    std::array<uint32_t, kTierCount> hidden{};
    /// Instances in the frustum not tested against the horizon (impostors by
    /// their size that no budget counts; LodManager::testEveryHorizon),
    /// counted in view: 0 when every instance is tested.
    uint32_t untested = 0;
    /// In view and drawn as impostors only because the far tier's budget
    /// was spent (their size asked for a mesh).
    uint32_t pastFarBudget = 0;
    uint32_t budgetDemoted = 0; ///< drawn coarser than their size asks, for the budget
    uint32_t tierChanges = 0;   ///< instances whose tier changed this frame
};

} // namespace tessera::lod
