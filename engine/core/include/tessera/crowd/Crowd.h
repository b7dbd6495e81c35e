#pragma once
/// @file Crowd.h
/// The instanced crowd's simulation: thousands of agents walking the
/// deformable terrain to goals, with no GPU. docs/CROWD.md describes the
/// model (continuum-crowd potential fields plus local avoidance, after the
/// Froblins) and its figures.

#include "tessera/core/Result.h"
#include "tessera/crowd/CrowdAgents.h"
#include "tessera/crowd/CrowdSettings.h"
#include "tessera/crowd/CrowdStats.h"
#include "tessera/crowd/GoalGroup.h"
#include "tessera/crowd/NavGrid.h"
#include "tessera/crowd/PotentialField.h"
#include "tessera/crowd/SpawnPattern.h"
#include "tessera/scene/Aabb.h"
#include "tessera/scene/Frustum.h"
#include "tessera/scene/NodeId.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <span>
#include <vector>

namespace tessera {
class Random;
}
namespace tessera::scene {
class SceneGraph;
}

namespace tessera::crowd {

class Navigation;
class AgentBins;
class NeighbourGrid;
struct TileAgents;
struct AgentState;

/// A crowd on a terrain. Each step():
///  1. fields: craters made since the last step (Terrain::splatHistory) turn
///     their area into a hazard and make agents near them flee; expired
///     hazards are lifted; every densityUpdateSeconds the agents are
///     splatted into the cost; the potential fields settle within the tile
///     budget;
///  2. avoidance: each agent's preferred velocity comes from its group's
///     field (or fleeing, or walking off impassable ground), and ORCA picks
///     the velocity nearest it that avoids its nearest neighbours and the
///     walls;
///  3. integration: agents move, overlaps left over are pushed apart and out
///     of walls, agents stand on Terrain::heightAt, headings turn at a
///     bounded rate, clips and phases advance with distance walked, arrivals
///     take new goals, and the bounds hierarchy is rebuilt.
///
/// Deterministic: the same inputs and step count give bit-identical agents
/// with any CrowdSettings::threads. The terrain must outlive the crowd.
class Crowd {
public:
    /// Most agents one crowd holds.
    static constexpr uint64_t kMaxAgents = 1u << 24;

    /// Checks the inputs, builds the navigation grid over `terrain`, spawns
    /// every pattern and solves the fields. Errors name the goal or pattern
    /// at fault: a region off the terrain or without walkable ground, a goal
    /// index out of range, more agents than a region holds, bad settings.
    static Result<std::unique_ptr<Crowd>> create(const terrain::Terrain& terrain, const CrowdSettings& settings,
                                                 std::span<const GoalGroup> goals,
                                                 std::span<const SpawnPattern> spawns);
    /// Memory a crowd of `agents` agents with `groups` goal groups needs on
    /// `terrain`, to refuse before trying.
    static CrowdMemory estimateMemory(const terrain::Terrain& terrain, const CrowdSettings& settings,
                                      uint64_t agents, uint32_t groups);

    ~Crowd();
    Crowd(const Crowd&) = delete;
    Crowd& operator=(const Crowd&) = delete;

    /// Advances by settings().timeStep.
    void step();

    /// The agents. Their order changes every few steps (they are re-sorted
    /// in memory by where they stand); follow one agent by its id.
    const CrowdAgents& agents() const { return mAgents; }
    /// The current index of the agent with stable id `id` (ids are 0 to
    /// agents().size() - 1).
    uint32_t indexOf(uint32_t id) const { return mIndexOf[id]; }
    std::span<const GoalGroup> goals() const { return mGoals; }
    const CrowdSettings& settings() const { return mSettings; }
    const NavGrid& navGrid() const;
    const PotentialField& field(uint32_t group) const;
    /// Whether world point `p` is passable now (ground not too steep, no
    /// fresh crater).
    bool passable(glm::vec2 p) const;
    /// Seconds simulated and steps taken.
    double time() const { return mTime; }
    uint64_t stepCount() const { return mSteps; }
    const CrowdStats& stats() const { return mStats; }
    const CrowdTimings& lastTimings() const { return mTimings; }
    CrowdMemory memory() const;

    /// Every agent's box (empty without agents).
    const scene::Aabb& bounds() const;
    /// Appends the agents that may be inside `frustum`, through the bounds
    /// hierarchy (tiles of NavGrid::kTileCells cells, merged 2 x 2 upwards).
    void cull(const scene::Frustum& frustum, std::vector<uint32_t>& out) const;
    /// Measures how many pairs overlap (all pairs within reach).
    OverlapReport measureOverlap() const;

    /// Makes the crowd one node of `graph` under `parent` (tagged
    /// `kind`, payload 0), whose bounds follow the agents at every step. The
    /// graph must outlive the attachment; detach() ends it.
    scene::NodeId attach(scene::SceneGraph& graph, scene::NodeId parent = {}, uint32_t kind = 0);
    void detach();

private:
    Crowd(const terrain::Terrain& terrain, const CrowdSettings& settings, std::span<const GoalGroup> goals);
    Status spawn(std::span<const SpawnPattern> spawns);
    float neighbourCellSize() const;
    TileAgents tileAgents() const;
    void reactToTerrain();
    void splatDensity();
    void steer();
    void integrate();
    void separate();
    void finishStep();
    void publish();
    void arrive(uint32_t agent);
    void pickSpot(uint32_t agent, glm::vec2 inward, Random& random);

    const terrain::Terrain& mTerrain;
    CrowdSettings mSettings;
    std::vector<GoalGroup> mGoals;
    CrowdAgents mAgents;
    std::vector<uint32_t> mIndexOf; ///< id -> index
    std::unique_ptr<AgentState> mState;
    std::unique_ptr<Navigation> mNavigation;
    std::unique_ptr<AgentBins> mBins;
    std::unique_ptr<NeighbourGrid> mNeighbours;
    size_t mSplatsSeen = 0;
    float mLargestRadius = 0.0f;
    float mFastest = 0.0f; ///< the highest preferred speed
    double mTime = 0.0;
    double mNextDensity = 0.0;
    uint64_t mSteps = 0;
    uint64_t mArrivals = 0;
    CrowdStats mStats;
    CrowdTimings mTimings;
    scene::SceneGraph* mGraph = nullptr;
    scene::NodeId mNode;
};

} // namespace tessera::crowd
