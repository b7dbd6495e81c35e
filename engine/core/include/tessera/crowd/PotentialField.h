#pragma once
/// @file PotentialField.h
/// One goal group's potential: the cost-weighted distance to its goal over
/// the navigation grid, the solution of the eikonal equation |grad phi| = C
/// (continuum crowds). Agents walk down its gradient.

#include "tessera/crowd/NavGrid.h"
#include "tessera/crowd/Region.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace tessera::crowd {

/// Potential per cell: 0 on the goal's walkable cells, infinite where the
/// goal cannot be reached, and elsewhere the least integral of the cost
/// along any path to the goal (metres of flat ground).
///
/// The field is solved incrementally, tile by tile (the fast iterative
/// method on 16 x 16 tiles, fast sweeping inside a tile; FieldSolver drives
/// it): tiles whose inputs changed are *active*, and solving one may
/// activate its neighbours. Where costs rise sharply (a fresh crater, ground
/// made too steep), invalidateDependents() first resets every cell whose
/// value was derived through the changed cells, so stale low values cannot
/// trap agents; smaller rises and all decreases settle by re-solving.
class PotentialField {
public:
    static constexpr float kUnreachable = NavGrid::kImpassable;

    PotentialField(const NavGrid& grid, const Region& goal);

    const Region& goal() const { return mGoal; }
    /// The value of cell `index`.
    float at(uint32_t index) const { return mPhi[index]; }
    std::span<const float> values() const { return mPhi; }
    /// The potential at world point `p`, bilinear between cell centres
    /// (kUnreachable when the cells around are all unreachable).
    float sample(glm::vec2 p) const;
    /// Whether the cell under `p` has a route to the goal.
    bool reachable(glm::vec2 p) const;
    /// Unit direction of steepest descent at `p`, from the bilinear
    /// interpolant between cell centres; unreachable cells count as higher
    /// than every reachable neighbour, so the direction leads away from
    /// walls. Zero on flat ground (inside the goal) and where unreachable.
    glm::vec2 descent(glm::vec2 p) const;

    /// Tiles waiting to be solved.
    uint32_t activeTileCount() const { return uint32_t(mActive.size()); }

    // --- The incremental solver's interface (FieldSolver) -----------------

    /// Cells this close to the goal (in cells) take their potential from the
    /// exact distance to the goal's outline rather than from the scheme:
    /// a staircase of cells around a disc would otherwise err by up to half a
    /// cell from the start.
    static constexpr float kExactReach = 1.5f;
    /// The fixed potential of cell (i, j) of ground cost `cost` when it is
    /// at or next to the goal (0 inside, distance times cost just outside),
    /// else a negative value: solve it.
    float fixedValue(uint32_t i, uint32_t j, float cost) const {
        const float d = mGoal.distanceTo(mGrid->cellCenter(i, j));
        return d <= kExactReach * mGrid->cellSize() ? d * cost : -1.0f;
    }
    /// Marks `tile` for solving with priority `key` (lower first: roughly the
    /// potential of the wavefront reaching it).
    void activate(uint32_t tile, float key);
    /// Activates `tile` keyed by its current lowest value.
    void activateByContent(uint32_t tile);
    /// Activates every tile the goal touches (a solve from scratch).
    void activateGoalTiles();
    /// Resets to unreachable every cell whose value depended, through any
    /// chain of upwind neighbours, on one of `cells` (those included), and
    /// activates the tiles around them. `highestCost(cell)` bounds the cost
    /// of leaving a cell in any direction; cells outside `cells` must have
    /// the costs their values were computed with.
    void invalidateDependents(std::span<const uint32_t> cells, const std::function<float(uint32_t)>& highestCost);
    /// Removes up to `count` active tiles, lowest key first (ties: lower
    /// index), into `out`.
    void takeTiles(uint32_t count, std::vector<uint32_t>& out);
    /// Mutable values, for the solver's write-back.
    std::span<float> mutableValues() { return mPhi; }

private:
    // Inline: descent() reads four cells for every walking agent every step.
    float cellValue(int32_t i, int32_t j) const {
        return mGrid->inGrid(i, j) ? mPhi[mGrid->index(uint32_t(i), uint32_t(j))] : kUnreachable;
    }

    const NavGrid* mGrid;
    Region mGoal;
    std::vector<float> mPhi;
    std::vector<float> mTileKey;        ///< per tile, meaningful while active
    std::vector<uint8_t> mTileActive;   ///< per tile
    std::vector<uint32_t> mActive;      ///< active tiles, unordered
    std::vector<uint8_t> mMark;         ///< per cell, scratch of invalidateDependents (zero between calls)
};

} // namespace tessera::crowd
