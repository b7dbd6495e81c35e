#include "tessera/crowd/Crowd.h"

#include "AgentState.h"
#include "CrowdChecks.h"
#include "Navigation.h"
#include "tessera/core/Random.h"

#include <cmath>
#include <numbers>
#include <vector>

namespace tessera::crowd {
namespace {

// Random placement tries this many spots per agent before giving up.
constexpr uint32_t kSpawnAttempts = 200;

// Placed agents by square cell of the largest diameter, to test overlap.
// A flat hash of the occupied cells (open addressing, linear probing) to the
// last agent placed in each, and per agent the one placed before it in its
// cell: no allocation per agent or cell, where a map of vectors made a
// million-agent spawn allocation-bound (a second of the creation, serial).
class PlacementGrid {
public:
    PlacementGrid(float cell, size_t agents) : mCell(cell) {
        size_t capacity = 64;
        while (capacity < 2 * agents) capacity *= 2;
        mKeys.assign(capacity, kEmpty);
        mHeads.resize(capacity);
        mNext.reserve(agents);
    }
    bool free(glm::vec2 p, float r, const CrowdAgents& agents) const {
        const int64_t cx = cellOf(p.x), cz = cellOf(p.y);
        for (int64_t z = cz - 1; z <= cz + 1; ++z)
            for (int64_t x = cx - 1; x <= cx + 1; ++x) {
                const size_t slot = find(key(x, z));
                if (mKeys[slot] == kEmpty) continue;
                for (uint32_t a = mHeads[slot]; a != kNone; a = mNext[a]) {
                    const glm::vec2 q(agents.position[a].x, agents.position[a].z);
                    const float reach = r + agents.radius[a];
                    if (glm::dot(p - q, p - q) < reach * reach) return false;
                }
            }
        return true;
    }
    /// Agents are added in index order 0, 1, 2, ...
    void add(glm::vec2 p, uint32_t agent) {
        const uint64_t k = key(cellOf(p.x), cellOf(p.y));
        const size_t slot = find(k);
        const bool fresh = mKeys[slot] == kEmpty;
        mKeys[slot] = k;
        mNext.push_back(fresh ? kNone : mHeads[slot]);
        mHeads[slot] = agent;
    }

private:
    static constexpr uint64_t kEmpty = ~uint64_t(0);
    static constexpr uint32_t kNone = ~uint32_t(0);
    int64_t cellOf(float v) const { return int64_t(std::floor(v / mCell)); }
    // Cells are within +-2^31 of the origin, so the key is never kEmpty.
    static uint64_t key(int64_t x, int64_t z) { return (uint64_t(uint32_t(x)) << 32) | uint64_t(uint32_t(z)); }
    // The slot holding `k`, or the empty one where it would go.
    size_t find(uint64_t k) const {
        const size_t mask = mKeys.size() - 1;
        size_t slot = size_t((k * 0x9E3779B97F4A7C15ull) >> 20) & mask;
        while (mKeys[slot] != kEmpty && mKeys[slot] != k) slot = (slot + 1) & mask;
        return slot;
    }
    float mCell;
    std::vector<uint64_t> mKeys;  ///< per slot: the cell's key, or kEmpty
    std::vector<uint32_t> mHeads; ///< per slot: the last agent placed in the cell
    std::vector<uint32_t> mNext;  ///< per agent: the agent placed before it in its cell, or kNone
};

} // namespace

Status Crowd::spawn(std::span<const SpawnPattern> spawns) {
    const NavGrid& grid = navGrid();
    const uint32_t groups = uint32_t(mGoals.size());
    size_t total = 0;
    float largest = 0.05f;
    for (size_t k = 0; k < spawns.size(); ++k) {
        if (Status ok = checkSpawn(spawns[k], k, groups, grid); !ok) return ok;
        total += spawns[k].count;
        largest = std::max(largest, spawns[k].radiusMax);
    }
    CrowdAgents& a = mAgents;
    a.position.reserve(total), a.velocity.reserve(total), a.heading.reserve(total), a.radius.reserve(total);
    a.preferredSpeed.reserve(total), a.goalGroup.reserve(total), a.clip.reserve(total), a.phase.reserve(total);
    a.id.reserve(total);
    PlacementGrid placed(2.0f * largest, total);
    for (size_t k = 0; k < spawns.size(); ++k) {
        const SpawnPattern& spawn = spawns[k];
        Random random(spawn.seed, k);
        for (uint32_t n = 0; n < spawn.count; ++n) {
            const float radius = random.range(spawn.radiusMin, spawn.radiusMax);
            const uint32_t index = uint32_t(a.position.size());
            const uint32_t group = spawn.goalGroup == SpawnPattern::kEveryGroup ? index % groups : spawn.goalGroup;
            const PotentialField& field = mNavigation->field(group);
            bool found = false;
            glm::vec2 p(0.0f);
            for (uint32_t attempt = 0; attempt < kSpawnAttempts && !found; ++attempt) {
                p = spawn.region.pointAt(random.nextFloat(), random.nextFloat());
                found = grid.walkable(p) && (!spawn.reachableOnly || field.reachable(p)) && placed.free(p, radius, a);
            }
            if (!found && spawn.reachableOnly && !hasReachableGround(grid, spawn.region, field))
                return fail("crowd: spawn pattern ", std::to_string(k), ": no walkable ground in region ",
                            describe(spawn.region), " from which ", goalName(mGoals, group),
                            " can be reached (steep slopes cut it off)");
            if (!found)
                return fail("crowd: spawn pattern ", std::to_string(k), ": placed ", std::to_string(n), " of ",
                            std::to_string(spawn.count), " agents; no free walkable spot",
                            spawn.reachableOnly ? " with a route to the goal" : "", " left in region ",
                            describe(spawn.region), " (use a larger region or fewer agents)");
            placed.add(p, index);
            a.position.emplace_back(p.x, mTerrain.heightAt(p.x, p.y), p.y);
            a.velocity.emplace_back(0.0f);
            a.heading.push_back(random.range(-std::numbers::pi_v<float>, std::numbers::pi_v<float>));
            a.radius.push_back(radius);
            a.preferredSpeed.push_back(random.range(spawn.speedMin, spawn.speedMax));
            a.goalGroup.push_back(uint16_t(group));
            a.clip.push_back(AgentClip::Idle);
            a.phase.push_back(random.nextFloat());
            a.id.push_back(index);
        }
    }
    mState->resize(total);
    mIndexOf.resize(total);
    for (uint32_t i = 0; i < uint32_t(total); ++i) mIndexOf[i] = i;
    mLargestRadius = total ? largest : 0.0f;
    for (float speed : a.preferredSpeed) mFastest = std::max(mFastest, speed);
    return {};
}

} // namespace tessera::crowd
