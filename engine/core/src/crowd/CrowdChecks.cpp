#include "CrowdChecks.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace tessera::crowd {
namespace {

std::string metres(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", double(v));
    return text;
}

bool inRange(float v, float lo, float hi) { return std::isfinite(v) && v >= lo && v <= hi; }

Status range(const char* name, float v, float lo, float hi) {
    if (inRange(v, lo, hi)) return {};
    return fail("crowd settings: ", name, " is ", metres(v), "; it must be between ", metres(lo), " and ", metres(hi));
}

// Densest packing random placement reliably reaches (random sequential
// adsorption jams near 0.55 of the area); a margin below it.
constexpr float kSpawnPacking = 0.4f;

} // namespace

std::string describe(const Region& region) {
    if (region.shape == Region::Shape::Disc)
        return "disc at (" + metres(region.center.x) + ", " + metres(region.center.y) + ") radius " +
               metres(region.halfSize.x) + " m";
    const glm::vec2 lo = region.boundsMin(), hi = region.boundsMax();
    return "rectangle (" + metres(lo.x) + ", " + metres(lo.y) + ") to (" + metres(hi.x) + ", " + metres(hi.y) + ") m";
}

std::string goalName(std::span<const GoalGroup> goals, size_t index) {
    return goals[index].name.empty() ? "goal " + std::to_string(index) : "goal '" + goals[index].name + "'";
}

Status checkSettings(const CrowdSettings& s, const terrain::Terrain& terrain) {
    const Status checks[] = {
        range("timeStep", s.timeStep, 1e-4f, 1.0f),
        range("cellSize", s.cellSize, 0.25f, 64.0f),
        range("maxSlopeDegrees", s.maxSlopeDegrees, 1.0f, 89.0f),
        range("slopeSpeedAtLimit", s.slopeSpeedAtLimit, 0.01f, 1.0f),
        range("densityMin", s.densityMin, 0.0f, 100.0f),
        range("densityMax", s.densityMax, s.densityMin + 1e-3f, 100.0f),
        range("densityCostWeight", s.densityCostWeight, 0.0f, 100.0f),
        range("flowSpeed", s.flowSpeed, 0.01f, 100.0f),
        range("densityUpdateSeconds", s.densityUpdateSeconds, 0.0f, 3600.0f),
        range("hazardSeconds", s.hazardSeconds, 0.0f, 1e6f),
        range("hazardMargin", s.hazardMargin, 0.0f, 1e4f),
        range("fleeRadiusFactor", s.fleeRadiusFactor, 0.0f, 100.0f),
        range("fleeSeconds", s.fleeSeconds, 0.0f, 3600.0f),
        range("fleeSpeedFactor", s.fleeSpeedFactor, 0.1f, 10.0f),
        range("neighbourRadius", s.neighbourRadius, 0.1f, 50.0f),
        range("horizonSeconds", s.horizonSeconds, 0.05f, 60.0f),
        range("comfortMargin", s.comfortMargin, 0.0f, 5.0f),
        range("maxAcceleration", s.maxAcceleration, 0.01f, 1e3f),
        range("maxTurnRate", s.maxTurnRate, 0.01f, 1e3f),
        range("agentHeight", s.agentHeight, 0.0f, 1e3f),
        range("walkStrideLength", s.walkStrideLength, 1e-3f, 1e3f),
        range("strideRadius", s.strideRadius, 1e-3f, 1e3f),
        range("idleCycleSeconds", s.idleCycleSeconds, 1e-3f, 1e3f),
        range("walkCycleSeconds", s.walkCycleSeconds, 1e-3f, 1e3f),
        range("minWalkRate", s.minWalkRate, 1e-2f, 1.0f),
        range("maxWalkRate", s.maxWalkRate, 1.0f, 10.0f),
        range("stuckSeconds", s.stuckSeconds, 0.0f, 1e6f),
        range("stuckProgress", s.stuckProgress, 0.0f, 1e6f),
    };
    for (const Status& check : checks)
        if (!check) return check;
    for (size_t k = 0; k < s.kinds.size(); ++k) {
        const WalkerKind& kind = s.kinds[k];
        const std::string name = "kinds[" + std::to_string(k) + "].";
        const Status kindChecks[] = {
            range((name + "walkStrideLength").c_str(), kind.walkStrideLength, 1e-3f, 1e3f),
            range((name + "walkCycleSeconds").c_str(), kind.walkCycleSeconds, 1e-3f, 1e3f),
            range((name + "idleCycleSeconds").c_str(), kind.idleCycleSeconds, 1e-3f, 1e3f),
        };
        for (const Status& check : kindChecks)
            if (!check) return check;
    }
    if (s.maxNeighbours < 1 || s.maxNeighbours > 16)
        return fail("crowd settings: maxNeighbours is ", std::to_string(s.maxNeighbours), "; it must be 1 to 16");
    if (s.separationIterations > 16)
        return fail("crowd settings: separationIterations is ", std::to_string(s.separationIterations),
                    "; at most 16");
    const glm::vec2 size = terrain.field().worldSize();
    if (size.x < s.cellSize || size.y < s.cellSize)
        return fail("crowd settings: cellSize ", metres(s.cellSize), " m is larger than the terrain (", metres(size.x),
                    " x ", metres(size.y), " m)");
    return {};
}

Status checkGoals(std::span<const GoalGroup> goals) {
    if (goals.empty()) return fail("crowd: no goal groups; a crowd needs at least one goal");
    if (goals.size() > UINT16_MAX) return fail("crowd: ", std::to_string(goals.size()), " goal groups; at most 65535");
    for (size_t g = 0; g < goals.size(); ++g)
        if (!goals[g].region.valid())
            return fail("crowd: ", goalName(goals, g), ": region ", describe(goals[g].region),
                        " needs a positive, finite size");
    return {};
}

namespace {

// Walkable cells of `region` (centre inside) for which `accept(index)` holds.
template <class Accept>
uint32_t countCells(const NavGrid& grid, const Region& region, Accept&& accept) {
    const CellRect cells = grid.cellsTouching(region.boundsMin(), region.boundsMax());
    uint32_t count = 0;
    for (int32_t j = cells.j0; j <= cells.j1; ++j)
        for (int32_t i = cells.i0; i <= cells.i1; ++i) {
            const uint32_t index = grid.index(uint32_t(i), uint32_t(j));
            if (std::isfinite(grid.terrainCost(index)) && region.contains(grid.cellCenter(uint32_t(i), uint32_t(j))) &&
                accept(index))
                ++count;
        }
    return count;
}

} // namespace

float walkableArea(const NavGrid& grid, const Region& region) {
    return float(countCells(grid, region, [](uint32_t) { return true; })) * grid.cellSize() * grid.cellSize();
}

bool hasReachableGround(const NavGrid& grid, const Region& region, const PotentialField& field) {
    return countCells(grid, region, [&](uint32_t index) { return field.at(index) < PotentialField::kUnreachable; }) > 0;
}

Status checkWalkable(const NavGrid& grid, const Region& region, const std::string& what) {
    const glm::vec2 lo = region.boundsMin(), hi = region.boundsMax(), size = grid.worldSize();
    if (hi.x < 0.0f || hi.y < 0.0f || lo.x > size.x || lo.y > size.y)
        return fail("crowd: ", what, ": region ", describe(region), " lies outside the terrain (0 to ",
                    metres(size.x), " m along X and 0 to ", metres(size.y), " m along Z)");
    if (walkableArea(grid, region) <= 0.0f)
        return fail("crowd: ", what, ": region ", describe(region),
                    " has no walkable ground (too steep everywhere, or smaller than one ", metres(grid.cellSize()),
                    " m navigation cell)");
    return {};
}

Status checkSpawn(const SpawnPattern& spawn, size_t index, uint32_t groups, const NavGrid& grid) {
    const std::string what = "spawn pattern " + std::to_string(index);
    if (!spawn.region.valid())
        return fail("crowd: ", what, ": region ", describe(spawn.region), " needs a positive, finite size");
    if (spawn.goalGroup != SpawnPattern::kEveryGroup && spawn.goalGroup >= groups)
        return fail("crowd: ", what, ": goal group ", std::to_string(spawn.goalGroup), " does not exist (there are ",
                    std::to_string(groups), ")");
    if (!inRange(spawn.radiusMin, 0.05f, 0.5f * grid.cellSize()) || !inRange(spawn.radiusMax, spawn.radiusMin, 0.5f * grid.cellSize()))
        return fail("crowd: ", what, ": radii ", metres(spawn.radiusMin), " to ", metres(spawn.radiusMax),
                    " m; they must be from 0.05 m to half a navigation cell (", metres(0.5f * grid.cellSize()),
                    " m), smallest first");
    if (!inRange(spawn.speedMin, 0.0f, 20.0f) || !inRange(spawn.speedMax, spawn.speedMin, 20.0f))
        return fail("crowd: ", what, ": speeds ", metres(spawn.speedMin), " to ", metres(spawn.speedMax),
                    " m/s; they must be from 0 to 20 m/s, slowest first");
    if (spawn.count == 0) return {};
    if (Status ok = checkWalkable(grid, spawn.region, what); !ok) return ok;
    const float area = walkableArea(grid, spawn.region);
    const float footprint = std::numbers::pi_v<float> * spawn.radiusMax * spawn.radiusMax;
    const double holds = std::floor(double(area) * kSpawnPacking / double(footprint));
    if (double(spawn.count) > holds)
        return fail("crowd: ", what, ": ", std::to_string(spawn.count), " agents of radius up to ",
                    metres(spawn.radiusMax), " m do not fit on the ", std::to_string(int64_t(area)),
                    " square metres of walkable ground in region ", describe(spawn.region), " (at most ",
                    std::to_string(int64_t(holds)), "); use a larger region or fewer agents");
    return {};
}

} // namespace tessera::crowd
