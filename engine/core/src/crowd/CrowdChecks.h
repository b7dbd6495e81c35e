#pragma once
// Internal: the checks Crowd::create makes on its inputs, each returning a
// message that names the setting, goal or spawn pattern at fault.

#include "tessera/core/Result.h"
#include "tessera/crowd/CrowdSettings.h"
#include "tessera/crowd/GoalGroup.h"
#include "tessera/crowd/NavGrid.h"
#include "tessera/crowd/PotentialField.h"
#include "tessera/crowd/Region.h"
#include "tessera/crowd/SpawnPattern.h"
#include "tessera/terrain/Terrain.h"

#include <span>
#include <string>

namespace tessera::crowd {

/// "disc at (x, z) radius r" or "rectangle (x0, z0) to (x1, z1)", in metres.
std::string describe(const Region& region);
/// "goal 'name'" (or "goal 3" when unnamed).
std::string goalName(std::span<const GoalGroup> goals, size_t index);

Status checkSettings(const CrowdSettings& settings, const terrain::Terrain& terrain);
Status checkGoals(std::span<const GoalGroup> goals);
/// The region must touch the grid and hold at least one walkable cell.
Status checkWalkable(const NavGrid& grid, const Region& region, const std::string& what);
/// Walkable area of `region` on `grid` (cells whose centre is inside), m^2.
float walkableArea(const NavGrid& grid, const Region& region);
/// Whether some walkable cell of `region` has a route to `field`'s goal.
bool hasReachableGround(const NavGrid& grid, const Region& region, const PotentialField& field);
Status checkSpawn(const SpawnPattern& spawn, size_t index, uint32_t groups, const NavGrid& grid);

} // namespace tessera::crowd
