#pragma once
/// @file CrowdSetup.h
/// A crowd on any terrain, set up the way the crowd scene and `--bench
/// crowd-sim` both do: the agent count checked against the machine's memory,
/// spawn and goals planned on open ground (crowd::planCrowdLayout), every
/// agent dealt over the goal groups and wandering between them forever.

#include "tessera/core/Result.h"
#include "tessera/crowd/Crowd.h"
#include "tessera/crowd/CrowdLayout.h"
#include "tessera/crowd/SpawnPattern.h"
#include "tessera/terrain/Terrain.h"

#include <cstdint>
#include <memory>
#include <string>

namespace tessera::runtime {

/// Goal groups (one potential field each) and how far their goals lie from
/// the spawn's centre (metres).
inline constexpr uint32_t kCrowdGoalGroups = 4;
inline constexpr float kCrowdGoalDistance = 300.0f;

struct PlannedCrowd {
    crowd::CrowdLayout layout;
    std::unique_ptr<crowd::Crowd> crowd;
    double createMs = 0.0; ///< Crowd::create alone (the fields' first solve included)
};

/// Refuses a crowd of `agents` that would not fit in memory: the crowd's
/// estimate (Crowd::estimateMemory) against three quarters of the machine's
/// available memory, the rest left to the terrain, the renderer and the
/// system. The error names --agents and says how many agents would fit.
Status checkCrowdFits(const terrain::Terrain& terrain, const crowd::CrowdSettings& settings, uint64_t agents);

/// checkCrowdFits, then plans the layout for `agents` agents of `pattern`'s
/// largest radius (kCrowdGoalGroups goals at kCrowdGoalDistance, Wander)
/// and creates the crowd: `agents` agents in the spawn disc with `pattern`'s
/// radii, speeds and seed, dealt over every group. A terrain without room
/// for them gives planCrowdLayout's error as it is.
Result<PlannedCrowd> planCrowd(const terrain::Terrain& terrain, const crowd::CrowdSettings& settings, uint32_t agents,
                               const crowd::SpawnPattern& pattern);

/// "a 66 m spawn disc at (4698, 4202) with 4 goals 296 to 305 m away".
std::string describeLayout(const crowd::CrowdLayout& layout);

} // namespace tessera::runtime
