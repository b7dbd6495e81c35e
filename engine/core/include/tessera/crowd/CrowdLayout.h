#pragma once
/// @file CrowdLayout.h
/// Spawn and goal regions chosen automatically on open, connected ground,
/// for terrains nobody laid out by hand (the demo's, any --heightmap, the
/// benchmark's).

#include "tessera/core/Result.h"
#include "tessera/crowd/GoalGroup.h"
#include "tessera/crowd/NavGrid.h"
#include "tessera/crowd/Region.h"

#include <cstdint>
#include <vector>

namespace tessera::crowd {

struct CrowdLayout {
    Region spawn;                 ///< a disc holding the agents comfortably
    std::vector<GoalGroup> goals; ///< named "goal 1", "goal 2", ...
};

struct CrowdLayoutRequest {
    uint32_t agents = 1000;
    uint32_t groups = 4;
    float agentRadius = 0.45f;    ///< the largest agent radius
    float goalDistance = 400.0f;  ///< metres from the spawn's centre to each goal
    float goalRadius = 30.0f;
    ArrivalPolicy onArrival = ArrivalPolicy::Wander;
};

/// Finds the largest connected area of walkable cells on `grid`; centres
/// the spawn disc on its most open cell (furthest from impassable ground)
/// within reach of the terrain's centre, grown until its walkable part holds
/// the agents at a fifth of the densest packing; puts the goals at about
/// `goalDistance` in evenly spread directions, each on the most open cell of
/// the same area near its ideal spot. Deterministic. Fails, saying why, when
/// the terrain has no walkable area large enough.
Result<CrowdLayout> planCrowdLayout(const NavGrid& grid, const CrowdLayoutRequest& request);

} // namespace tessera::crowd
