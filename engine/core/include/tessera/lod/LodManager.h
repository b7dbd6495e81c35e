#pragma once
/// @file LodManager.h
/// The crowd's level-of-detail manager: per frame, the parameters every
/// backend's GPU culling and binning read (thresholds, and the cuts and
/// level cap that keep the frame within its budget), and the CPU reference
/// of the selection, which the tests compare every backend's lists with
/// (the null backend, like a GPU one, runs the per-instance rule on these
/// parameters). See docs/CROWD.md, "Rendering".
///
/// The per-instance rule is shader::tsLodUpdate (CrowdLod.h), shared with
/// the GPU passes; this class adds what needs the whole frame: the budget.
/// It keeps every instance's state word by id, as each backend keeps its
/// own copy on the GPU, so both evolve alike.

#include "tessera/lod/HorizonPyramid.h"
#include "tessera/lod/LodFrame.h"
#include "tessera/lod/LodInstance.h"
#include "tessera/lod/LodPolicy.h"

#include <array>
#include <span>
#include <vector>

namespace tessera::lod {

class LodManager {
public:
    /// The policy must validate (LodPolicy::validate); asserts otherwise.
    explicit LodManager(const LodPolicy& policy = {}, uint32_t threads = 0);

    const LodPolicy& policy() const { return mPolicy; }
    /// Takes effect at the next update; states are kept.
    void setPolicy(const LodPolicy& policy);

    /// Selects this frame's tiers for `instances` seen from `view`:
    /// culls, sorts by size with hysteresis, fits the budget, advances the
    /// cross-fades. Instance `character` fields index `characters`. An
    /// instance whose sphere is not finite, or has a negative radius, is out
    /// of view (every backend leaves such an instance out too).
    const LodFrame& update(std::span<const LodInstance> instances, std::span<const LodCharacter> characters,
                           const LodView& view);
    /// Whether updates fill LodFrame::tiers, the per-tier lists (default:
    /// yes). The counts and parameters come either way; a renderer that
    /// only needs those skips a million-entry list for a million agents.
    void keepLists(bool keep) { mLists = keep; }
    bool keepsLists() const { return mLists; }
    /// Whether every instance in the frustum is tested against the horizon
    /// (default: yes), or only those a budget can count: a candidate for a
    /// mesh tier, an incumbent of one, or a copy fading out of one. The rest
    /// (an impostor by its size, no mesh copy fading) cannot change the
    /// parameters, and every backend culls them itself on the GPU: the
    /// parameters, the mesh tiers' instance and triangle counts and their
    /// hidden counts are the same either way (not their fading counts: an
    /// instance coming out from behind the terrain into a mesh tier fades
    /// in from the impostor it was taken for, where the reference, and
    /// every GPU, pops it in). Untested instances are counted as impostors in view
    /// (LodFrame::untested), so the impostor tier's count, LodFrame::inView
    /// and the state words of impostors the terrain hides are then not the
    /// reference's (a state reads "impostor" where the reference's reads
    /// "none"), nor is LodFrame::hidden's impostor count; countHidden gives
    /// those on demand. At a million agents the test of the impostors was
    /// nearly all of the manager's time (docs/CROWD.md 6.1).
    void testEveryHorizon(bool every) { mEveryHorizon = every; }
    bool testsEveryHorizon() const { return mEveryHorizon; }
    /// The instances in the frustum the terrain hides, by the tier their
    /// size would take from their current state: the reference's
    /// LodFrame::hidden for the last update's view (its parameters and
    /// horizon), whatever testEveryHorizon says. Changes no state. Costs the
    /// horizon test of every instance in view (an untimed report's figure).
    std::array<uint32_t, kTierCount> countHidden(std::span<const LodInstance> instances) const;
    /// The last update's answer.
    const LodFrame& frame() const { return mFrame; }

    /// The state word (CrowdLod.h) instance `id` ended the last update with.
    uint32_t state(uint32_t id) const;
    /// Forgets every instance (as after a teleport of the camera: nothing
    /// fades in).
    void reset();

private:
    /// Per instance, from the first pass over the frame.
    struct Seen {
        float pixels = 0.0f;
        uint32_t candidate = TS_LOD_NONE; ///< TS_LOD_NONE: out of view
        uint32_t tier = TS_LOD_NONE;      ///< after the budget, filled tier by tier
        uint32_t hidden = TS_LOD_NONE;    ///< behind the terrain: the candidate it would have been
        bool tested = false;              ///< in view and tested against the horizon
    };

    /// Puts each instance's state at its index (mSlotState), moving them
    /// only when the ids moved since the last update.
    void bindSlots(std::span<const LodInstance> instances);
    void classify(std::span<const LodInstance> instances);
    void fitBudget(std::span<const LodInstance> instances, std::span<const LodCharacter> characters);
    void advance(std::span<const LodInstance> instances, std::span<const LodCharacter> characters);
    uint64_t nearTriangles(float pixels, const LodCharacter& character, float cap) const;

    LodPolicy mPolicy;
    uint32_t mThreads = 0;
    /// The current update's horizon grid (LodView::occluders) and its max
    /// pyramid: tsLodBehindTerrain's answer, faster.
    HorizonPyramid mHorizon;
    /// States by id as of the last time the instances' ids moved (the
    /// ids absent since keep theirs there); the live ones are by slot: the
    /// last update's instance i had id mSlotId[i] and state mSlotState[i];
    /// mSlotOf[id] is the slot an id was given when it last moved.
    std::vector<uint32_t> mState, mSlotState, mSlotId, mSlotOf;
    std::vector<Seen> mSeen;
    /// The instances in view that can count against a budgeted tier
    /// (classify fills it; fitBudget reads only these), and its per-chunk parts.
    std::vector<uint32_t> mBudgeted;
    std::vector<std::vector<uint32_t>> mChunkBudgeted;
    bool mLists = true;
    bool mEveryHorizon = true;
    /// Triangles of one cage triangle at each odd segment count 1..63 (the
    /// fractional-odd pattern's triangle count depends only on it).
    std::array<uint32_t, 64> mTrianglesPerCageTriangle{};
    LodFrame mFrame;
};

} // namespace tessera::lod
