#pragma once
// Internal: the crowd's global navigation: the grid, the combined cost, one
// potential field per goal group, and how terrain changes, hazards and
// density reach them.

#include "AgentBins.h"
#include "CostField.h"
#include "FieldSolver.h"
#include "tessera/crowd/CrowdSettings.h"
#include "tessera/crowd/GoalGroup.h"
#include "tessera/crowd/NavGrid.h"
#include "tessera/crowd/PotentialField.h"
#include "tessera/terrain/CraterSplat.h"
#include "tessera/terrain/Terrain.h"

#include <memory>
#include <span>
#include <vector>

namespace tessera::crowd {

class Navigation {
public:
    Navigation(const terrain::Terrain& terrain, const CrowdSettings& settings, std::span<const GoalGroup> goals);

    const NavGrid& grid() const { return mGrid; }
    const CostField& cost() const { return mCost; }
    const PotentialField& field(uint32_t group) const { return *mFields[group]; }
    uint32_t groupCount() const { return uint32_t(mFields.size()); }

    /// Solves every field from scratch, to convergence.
    void solveAll();
    /// Solves what is waiting, to convergence.
    void settle();
    /// A crater landed: re-reads the ground's slope around it and makes it
    /// a hazard until `now + hazardSeconds`. Returns the hazard.
    Hazard addCrater(const terrain::Terrain& terrain, const terrain::CraterSplat& splat, double now);
    /// Lifts the hazards expired at `now`.
    void expireHazards(double now);
    /// Splats the agents' density, velocities and intended directions (unit,
    /// or zero for agents that want to go nowhere) into the cost (tiles
    /// occupied now or at the last splat).
    void updateDensity(const AgentBins& bins, std::span<const glm::vec3> positions,
                       std::span<const glm::vec2> velocities, std::span<const glm::vec2> intentions);
    /// Spends up to the settings' tile budget settling the fields; returns
    /// the tile solves done.
    uint32_t solve();
    /// Tiles of all fields still waiting.
    uint32_t activeTiles() const;

    /// Direction out of impassable ground at `p`: away from the hazard it is
    /// in, else towards the nearest passable cell within a few cells; zero
    /// when there is none.
    glm::vec2 escapeDirection(glm::vec2 p) const;
    size_t bytes() const;

private:
    /// Hands cost changes to every field: resets what depended on sharp
    /// rises, wakes the changed tiles.
    void apply(const CostChanges& changes);
    void recompute(const std::vector<uint32_t>& tiles);

    const CrowdSettings mSettings;
    NavGrid mGrid;
    CostField mCost;
    std::vector<std::unique_ptr<PotentialField>> mFields;
    FieldSolver mSolver;
    std::vector<uint32_t> mDensityTiles; ///< holding samples since the last density splat
};

} // namespace tessera::crowd
