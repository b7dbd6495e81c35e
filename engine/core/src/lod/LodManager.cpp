#include "tessera/lod/LodManager.h"

#include "LodAdmission.h"
#include "tessera/core/ParallelFor.h"
#include "tessera/tessellator/Tessellator.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>

namespace tessera::lod {
namespace {

using detail::AdmissionItem;

constexpr uint32_t kGrain = 4096;
// Instances whose horizon is proven together (HorizonPyramid::proveGroup).
constexpr uint32_t kHorizonGroup = 32;

bool continuesFadeFrom(uint32_t state, uint32_t tier) {
    // A fade with two or more frames left still draws the copy after this
    // frame's update, unless the instance changes tier again (then the copy
    // goes: counting it is conservative).
    return shader::tsLodStatePrevious(state) == tier && shader::tsLodStateTier(state) != tier &&
           shader::tsLodStateFade(state) >= 2u;
}

// Whether `sphere` meets the frustum. A sphere that is not finite is never
// in view: the backends leave such an instance out
// (backend::crowdInstanceValid), and its bounds would make a group's horizon
// proof meaningless.
bool inFrustum(const glm::vec4& sphere, const shader::CrowdLodParams& p) {
    const bool finite = std::isfinite(sphere.x) && std::isfinite(sphere.y) && std::isfinite(sphere.z) &&
                        std::isfinite(sphere.w) && sphere.w >= 0.0f;
    return finite && shader::tsLodInFrustum(sphere, p);
}

// Whether an instance in view (its candidate after the horizon: not none)
// can count against a budgeted tier's limits: as a candidate, an incumbent
// or a fading copy. The rest (impostors staying impostors, most of a large
// crowd) never reach fitBudget, which then reads thousands, not millions.
bool meetsTheBudgets(uint32_t candidate, uint32_t state) {
    const uint32_t previous = shader::tsLodStatePrevious(state);
    return candidate <= TS_LOD_FAR || shader::tsLodStateTier(state) <= TS_LOD_FAR ||
           (previous <= TS_LOD_FAR && continuesFadeFrom(state, previous));
}

} // namespace

LodManager::LodManager(const LodPolicy& policy, uint32_t threads) : mPolicy(policy), mThreads(threads) {
    assert(policy.validate().ok());
    for (uint32_t n = 1; n < mTrianglesPerCageTriangle.size(); n += 2) {
        tessellator::TessFactors factors;
        const float level = float(n);
        factors.outer = {level, level, level, level};
        factors.inner = {level, level};
        mTrianglesPerCageTriangle[n] = tessellator::Tessellator::countTriangles(
            tessellator::Domain::Triangle, tessellator::Partitioning::FractionalOdd, factors);
        mTrianglesPerCageTriangle[n + 1] = mTrianglesPerCageTriangle[n];
    }
}

void LodManager::setPolicy(const LodPolicy& policy) {
    assert(policy.validate().ok());
    mPolicy = policy;
}

uint32_t LodManager::state(uint32_t id) const {
    if (id < mSlotOf.size()) {
        const uint32_t slot = mSlotOf[id];
        if (slot < mSlotId.size() && mSlotId[slot] == id) return mSlotState[slot];
    }
    return id < mState.size() ? mState[id] : shader::tsLodStateNone();
}

void LodManager::reset() {
    mState.clear();
    mSlotState.clear();
    mSlotId.clear();
    mSlotOf.clear();
}

void LodManager::bindSlots(std::span<const LodInstance> instances) {
    const uint32_t count = uint32_t(instances.size());
    // Most frames the instances come with the same ids in the same places (a
    // crowd re-sorts its agents in memory now and then): the states stay in
    // instance order, read and written in sequence. A state by id, read at
    // random, was most of the frame's classification at a million agents.
    std::atomic<bool> moved = mSlotId.size() != count;
    if (!moved)
        core::parallelForRanges(count, kGrain, mThreads, [&](core::IndexRange range) {
            for (uint32_t i = range.begin; i < range.end && !moved.load(std::memory_order_relaxed); ++i)
                if (instances[i].id != mSlotId[i]) moved = true;
        });
    if (!moved) return;
    // Park last frame's states by id (ids absent now keep theirs, as each
    // backend's state buffer does), then fetch this frame's in its order.
    uint32_t maxId = 0;
    for (const LodInstance& instance : instances) maxId = std::max(maxId, instance.id);
    if (!instances.empty() && mState.size() <= maxId) mState.resize(size_t(maxId) + 1, shader::tsLodStateNone());
    core::parallelForRanges(uint32_t(mSlotId.size()), kGrain, mThreads, [&](core::IndexRange range) {
        for (uint32_t slot = range.begin; slot < range.end; ++slot) mState[mSlotId[slot]] = mSlotState[slot];
    });
    mSlotState.resize(count);
    mSlotId.resize(count);
    if (mSlotOf.size() < mState.size()) mSlotOf.resize(mState.size(), UINT32_MAX);
    core::parallelForRanges(count, kGrain, mThreads, [&](core::IndexRange range) {
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const uint32_t id = instances[i].id;
            mSlotId[i] = id;
            mSlotState[i] = mState[id];
            mSlotOf[id] = i;
        }
    });
}

uint64_t LodManager::nearTriangles(float pixels, const LodCharacter& character, float cap) const {
    shader::CrowdLodParams params = mFrame.params;
    params.levels.x = cap;
    const float level = shader::tsLodLevel(pixels, character.levelPerPixel, params);
    // Fractional-odd spacing rounds the level up to an odd segment count.
    uint32_t segments = uint32_t(std::ceil(level));
    segments = std::min<uint32_t>(segments | 1u, 63u);
    return uint64_t(character.cageTriangles) * mTrianglesPerCageTriangle[segments];
}

const LodFrame& LodManager::update(std::span<const LodInstance> instances, std::span<const LodCharacter> characters,
                                   const LodView& view) {
    LodFrame& f = mFrame;
    for (auto& tier : f.tiers) tier.clear();
    f.counts = {};
    f.inView = f.pastFarBudget = f.budgetDemoted = f.tierChanges = f.untested = 0;
    f.hidden = {};
    shader::CrowdLodParams& p = f.params;
    for (size_t i = 0; i < 6; ++i) p.planes[i] = view.frustum.planes()[i];
    p.eye = glm::vec4(view.eye, view.pixelsPerRadian);
    const bool occlusion = view.occluderGrid.w >= 1.0f && view.occluderGrid.z > 0.0f &&
                           view.occluders.size() >= size_t(view.occluderGrid.w) * size_t(view.occluderGrid.w);
    p.occluder = occlusion ? view.occluderGrid : glm::vec4(0.0f);
    mHorizon.build(occlusion ? view.occluders.data() : nullptr, occlusion ? uint32_t(view.occluderGrid.w) : 0u);
    p.thresholds = {mPolicy.nearPixels, mPolicy.farPixels, mPolicy.hysteresis, float(mPolicy.fadeFrames)};
    p.cuts = {0.0f, 0.0f, 0.0f, 0.0f}; // fitBudget sets them
    p.levels = {std::max(1.0f, view.maxLevel), mPolicy.fixedLevel, mPolicy.impostorPixels,
                1.0f / (1.0f - mPolicy.hysteresis)};

    bindSlots(instances);
    classify(instances);
    fitBudget(instances, characters);
    advance(instances, characters);
    return f;
}

void LodManager::classify(std::span<const LodInstance> instances) {
    mSeen.resize(instances.size());
    const shader::CrowdLodParams& p = mFrame.params;
    const uint32_t count = uint32_t(instances.size());
    mChunkBudgeted.resize((count + kGrain - 1) / kGrain);
    core::parallelForRanges(count, kGrain, mThreads, [&](core::IndexRange range) {
        std::vector<uint32_t>& budgeted = mChunkBudgeted[range.begin / kGrain];
        budgeted.clear();
        for (uint32_t group = range.begin; group < range.end; group += kHorizonGroup) {
            const uint32_t end = std::min(group + kHorizonGroup, range.end);
            // The group's spheres in view and their bounds: a crowd's agents
            // come in memory order, which keeps neighbours together, so the
            // horizon is often proven for the whole group at once.
            SphereBounds sight;
            for (uint32_t i = group; i < end; ++i) {
                Seen& seen = mSeen[i];
                seen.tier = TS_LOD_NONE;
                seen.hidden = TS_LOD_NONE;
                seen.tested = false;
                const glm::vec4& sphere = instances[i].sphere;
                if (!inFrustum(sphere, p)) {
                    seen.candidate = TS_LOD_NONE;
                    continue;
                }
                const uint32_t state = mSlotState[i];
                seen.pixels = shader::tsLodPixels(sphere, p);
                seen.candidate = shader::tsLodCandidate(seen.pixels, shader::tsLodStateTier(state), p);
                seen.tested = mEveryHorizon || meetsTheBudgets(seen.candidate, state);
                if (seen.tested) sight.add(sphere);
            }
            const GroupSight proof = sight.count ? mHorizon.proveGroup(sight, p) : GroupSight{};
            for (uint32_t i = group; i < end; ++i) {
                Seen& seen = mSeen[i];
                if (!seen.tested) continue;
                const LodInstance& instance = instances[i];
                const uint32_t state = mSlotState[i];
                if (mHorizon.behindTerrain(instance.sphere, p, proof)) {
                    seen.hidden = seen.candidate;
                    seen.candidate = TS_LOD_NONE;
                } else if (meetsTheBudgets(seen.candidate, state)) {
                    budgeted.push_back(i);
                }
            }
        }
    });
    // In instance order, as the chunks are.
    mBudgeted.clear();
    for (const std::vector<uint32_t>& chunk : mChunkBudgeted) mBudgeted.insert(mBudgeted.end(), chunk.begin(), chunk.end());
}

std::array<uint32_t, kTierCount> LodManager::countHidden(std::span<const LodInstance> instances) const {
    const shader::CrowdLodParams& p = mFrame.params;
    const uint32_t count = uint32_t(instances.size());
    std::vector<std::array<uint32_t, kTierCount>> chunks((count + kGrain - 1) / kGrain);
    core::parallelForRanges(count, kGrain, mThreads, [&](core::IndexRange range) {
        std::array<uint32_t, kTierCount>& hidden = chunks[range.begin / kGrain];
        hidden = {};
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const glm::vec4& sphere = instances[i].sphere;
            if (!inFrustum(sphere, p) || !mHorizon.behindTerrain(sphere, p)) continue;
            const uint32_t last = i < mSlotState.size() ? shader::tsLodStateTier(mSlotState[i]) : TS_LOD_NONE;
            ++hidden[shader::tsLodCandidate(shader::tsLodPixels(sphere, p), last, p)];
        }
    });
    std::array<uint32_t, kTierCount> total{};
    for (const auto& chunk : chunks)
        for (uint32_t t = 0; t < kTierCount; ++t) total[t] += chunk[t];
    return total;
}

void LodManager::fitBudget(std::span<const LodInstance> instances, std::span<const LodCharacter> characters) {
    shader::CrowdLodParams& p = mFrame.params;
    const LodBudget& budget = mPolicy.budget;
    const float maxLevel = p.levels.x;
    std::vector<AdmissionItem> items;

    // Fills `items` with tier `tier`'s candidates among the instances no
    // finer tier took, and sums the copies the others leave in it.
    auto gather = [&](uint32_t tier, float cap, uint64_t& forcedCost, uint64_t& forcedCount) {
        items.clear();
        forcedCost = forcedCount = 0;
        for (const uint32_t i : mBudgeted) {
            const Seen& seen = mSeen[i];
            const uint32_t state = mSlotState[i];
            const LodCharacter& character = characters[instances[i].character];
            const uint64_t cost = tier == TS_LOD_NEAR ? nearTriangles(seen.pixels, character, cap) : 1u;
            const bool wasHere = shader::tsLodStateTier(state) == tier;
            const bool candidate = seen.tier == TS_LOD_NONE && seen.candidate <= tier;
            if (candidate) {
                // Ranked as the GPU's cut compares it (tsLodTier).
                const float rank = tier == TS_LOD_FAR
                                       ? shader::tsLodFarRank(seen.pixels, shader::tsLodStateTier(state), p)
                                       : seen.pixels;
                items.push_back({rank, instances[i].id, i, cost, wasHere, continuesFadeFrom(state, tier)});
            } else if ((wasHere && seen.tier != tier) || continuesFadeFrom(state, tier)) {
                // Leaving the tier by its size, or for a finer one: a fading copy.
                forcedCost += cost;
                ++forcedCount;
            }
        }
    };
    auto admitTier = [&](uint32_t tier, float cap, const detail::AdmissionLimits& limits, bool fades) {
        uint64_t forcedCost = 0, forcedCount = 0;
        gather(tier, cap, forcedCost, forcedCount);
        return detail::admit(items, forcedCost, forcedCount, limits, fades);
    };
    auto take = [&](uint32_t tier, const detail::Admission& admission) {
        for (uint32_t k = 0; k < admission.admitted; ++k) mSeen[items[k].index].tier = tier;
    };
    // Incumbents of the tier `admission` leaves out (items as it ordered them).
    auto demotedIncumbents = [&](const detail::Admission& admission) {
        uint32_t n = 0;
        for (size_t k = admission.admitted; k < items.size(); ++k) n += items[k].copyIfDemoted;
        return n;
    };
    auto resetTiers = [&] {
        for (const uint32_t i : mBudgeted) mSeen[i].tier = TS_LOD_NONE;
    };

    const detail::AdmissionLimits nearLimits{budget.maxTessellatedTriangles, budget.maxNearInstances};
    const detail::AdmissionLimits middleLimits{UINT64_MAX, budget.maxMiddleInstances};
    const detail::AdmissionLimits farLimits{UINT64_MAX, budget.maxFarInstances};
    for (bool fades : {mPolicy.fadeFrames > 0, false}) {
        resetTiers();
        float cap = maxLevel;
        detail::Admission near = admitTier(TS_LOD_NEAR, cap, nearLimits, fades);
        if (near.fits && near.admitted == 0 && !items.empty()) {
            // Even the largest alone is over the triangle budget: lower the
            // frame's level cap, one odd segment count at a time, until it fits.
            for (int n = std::min(63, int(std::floor(maxLevel))) | 1; n >= 1; n -= 2) {
                const detail::Admission capped = admitTier(TS_LOD_NEAR, float(n), nearLimits, fades);
                if (capped.admitted > 0) {
                    cap = float(n);
                    near = capped;
                    break;
                }
            }
            if (near.admitted == 0) near = admitTier(TS_LOD_NEAR, cap, nearLimits, fades);
        }
        take(TS_LOD_NEAR, near);
        detail::Admission middle = admitTier(TS_LOD_MIDDLE, cap, middleLimits, fades);
        // The far mesh is made for creatures below the far threshold: the
        // middle budget never hands it a larger one (only those the
        // hysteresis keeps in the middle tier below it), so the middle tier
        // may hold more than its budget (docs/CROWD.md 6.2, "Fallbacks").
        if (middle.cut > mPolicy.farPixels) detail::admitDownTo(items, mPolicy.farPixels, middle);
        take(TS_LOD_MIDDLE, middle);
        // A full far tier (thousands of agents of nearly one size) admits a
        // newcomer larger than an incumbent only by demoting it, and a fading
        // demotion's copy keeps its place: with fades the cut would fall
        // below every incumbent the newcomer outranks, demoting them all.
        // Demote at once there when fading would demote more.
        detail::Admission far = admitTier(TS_LOD_FAR, cap, farLimits, fades);
        bool farFades = fades;
        if (fades) {
            const uint32_t fadingDemotions = demotedIncumbents(far);
            detail::Admission instant = admitTier(TS_LOD_FAR, cap, farLimits, false);
            if (demotedIncumbents(instant) < fadingDemotions) {
                far = instant;
                farFades = false;
            } else {
                far = admitTier(TS_LOD_FAR, cap, farLimits, true);
            }
        }
        take(TS_LOD_FAR, far);
        // The rest in view are impostors: that tier has no budget.
        const uint32_t fadeBits = fades ? ((1u << TS_LOD_NEAR) | (1u << TS_LOD_MIDDLE) |
                                           (farFades ? 1u << TS_LOD_FAR : 0u) | (1u << TS_LOD_IMPOSTOR))
                                        : 0u;
        p.cuts = {near.cut, middle.cut, far.cut, float(fadeBits)};
        p.levels.x = cap;
        // Fading copies of budget demotions that do not fit: demote at once.
        if (!fades || (near.fits && middle.fits && far.fits)) break;
    }
}

void LodManager::advance(std::span<const LodInstance> instances, std::span<const LodCharacter> characters) {
    struct Chunk {
        std::array<std::vector<LodDraw>, kTierCount> tiers;
        std::array<LodTierCount, kTierCount> counts{};
        uint32_t inView = 0, pastFar = 0, demoted = 0, changes = 0, untested = 0;
        std::array<uint32_t, kTierCount> hidden{};
    };
    const uint32_t count = uint32_t(instances.size());
    std::vector<Chunk> chunks((count + kGrain - 1) / kGrain);
    const shader::CrowdLodParams& p = mFrame.params;
    core::parallelForRanges(count, kGrain, mThreads, [&](core::IndexRange range) {
        Chunk& chunk = chunks[range.begin / kGrain];
        for (uint32_t i = range.begin; i < range.end; ++i) {
            const LodInstance& instance = instances[i];
            const Seen& seen = mSeen[i];
            const uint32_t old = mSlotState[i];
            if (seen.hidden != TS_LOD_NONE) ++chunk.hidden[seen.hidden];
            if (seen.candidate != TS_LOD_NONE && !seen.tested) ++chunk.untested;
            if (seen.candidate == TS_LOD_NONE) {
                mSlotState[i] = shader::tsLodStateNone();
                continue;
            }
            // tsLodUpdate's step for an instance in view, on classify's size
            // and candidate (the same numbers: no second frustum, horizon or
            // size test).
            const uint32_t next = shader::tsLodNext(old, seen.pixels, seen.candidate, p);
            mSlotState[i] = next;
            ++chunk.inView;
            const uint32_t tier = shader::tsLodStateTier(next);
            if (tier != seen.candidate) ++chunk.demoted;
            if (tier == TS_LOD_IMPOSTOR && seen.candidate != TS_LOD_IMPOSTOR) ++chunk.pastFar;
            const uint32_t last = shader::tsLodStateTier(old);
            if (last != TS_LOD_NONE && last != tier) ++chunk.changes;
            const LodCharacter& character = characters[instance.character];
            const float level = shader::tsLodLevel(seen.pixels, character.levelPerPixel, p);
            const float coverage = shader::tsLodCoverage(next, p);
            auto draw = [&](uint32_t t, float share, bool fadingOut) {
                const bool near = t == TS_LOD_NEAR;
                if (mLists) chunk.tiers[t].push_back({i, near ? level : 1.0f, share, fadingOut});
                LodTierCount& c = chunk.counts[t];
                ++c.instances;
                if (share < 1.0f) ++c.fading;
                c.triangles += near                 ? nearTriangles(seen.pixels, character, p.levels.x)
                               : t == TS_LOD_MIDDLE ? character.middleTriangles
                               : t == TS_LOD_FAR    ? character.farTriangles
                                                    : 2u;
            };
            draw(tier, coverage, false);
            if (shader::tsLodStateFade(next) > 0u) draw(shader::tsLodStatePrevious(next), 1.0f - coverage, true);
        }
    });
    LodFrame& f = mFrame;
    for (const Chunk& chunk : chunks) {
        for (uint32_t t = 0; t < kTierCount; ++t) {
            f.tiers[t].insert(f.tiers[t].end(), chunk.tiers[t].begin(), chunk.tiers[t].end());
            f.counts[t].instances += chunk.counts[t].instances;
            f.counts[t].fading += chunk.counts[t].fading;
            f.counts[t].triangles += chunk.counts[t].triangles;
        }
        f.inView += chunk.inView;
        f.untested += chunk.untested;
        for (uint32_t t = 0; t < kTierCount; ++t) f.hidden[t] += chunk.hidden[t];
        f.pastFarBudget += chunk.pastFar;
        f.budgetDemoted += chunk.demoted;
        f.tierChanges += chunk.changes;
    }
}

} // namespace tessera::lod
