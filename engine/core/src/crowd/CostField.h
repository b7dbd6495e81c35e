#pragma once
// Internal: the cost per metre of walking over every navigation cell that the
// potential fields are solved over: the ground (slope), fresh craters, and
// the crowd itself, which costs more to walk against than with.

#include "AgentBins.h"
#include "tessera/crowd/CrowdSettings.h"
#include "tessera/crowd/NavGrid.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tessera::crowd {

/// A fresh crater: impassable until `expires` (crowd seconds).
struct Hazard {
    glm::vec2 center{0.0f};
    float radius = 0.0f;
    double expires = 0.0;
};

/// What a cost update changed, for the fields: cells that became impassable
/// or much dearer (their dependents are reset) and tiles with any change
/// (re-solved).
struct CostChanges {
    std::vector<uint32_t> raised;
    std::vector<uint32_t> tiles;
    bool empty() const { return tiles.empty(); }
};

/// Directions of travel out of a cell, in this order.
enum Direction { kMinusX = 0, kPlusX = 1, kMinusZ = 2, kPlusZ = 3 };

/// Directed costs of one tile's cells: [cell][direction], cells row by row
/// (NavGrid::kTileCells wide, clipped tiles included).
using DirectedCosts = std::array<std::array<float, 4>, NavGrid::kTileCells * NavGrid::kTileCells>;

/// Two layers:
///  - ground: the terrain cost, or impassable inside a hazard. Isotropic; it
///    decides where agents may stand.
///  - crowding (continuum crowds, Treuille et al. 2006), per direction of
///    travel, from the agents' density, velocities and intended directions
///    (each agent's wish counts where it stands and a few metres on, so
///    others keep out of the way it is about to take):
///     * the speed the crowd lets one walk ahead: from a free walk to the
///       crowd's own velocity along that direction as density rises (with a
///       dense stream cheap, against it or into a standing crowd dear);
///     * walking against those who want to go the other way, whether they
///       move or stand in a jam;
///     * keeping right: oncoming walkers ahead and to the right, across the
///       width of a passage, make each direction's cheapest way its own
///       right side, so opposing groups take opposite sides of a passage
///       before they meet (lanes instead of a jam).
///    Read from summed-area tables of the samples around each tile; costs
///    are quantised to eighths so small fluctuations do not wake the solver.
///    Stored only for tiles near agents; elsewhere every direction costs the
///    ground cost.
class CostField {
public:
    CostField(const NavGrid& grid, const CrowdSettings& settings);
    ~CostField();

    /// Ground cost per cell (kImpassable where nobody may stand).
    std::span<const float> cost() const { return mCost; }
    bool passable(uint32_t cell) const { return mCost[cell] < NavGrid::kImpassable; }
    /// Whether world point `p` lies on a passable cell of the grid.
    bool passableAt(glm::vec2 p) const {
        const glm::ivec2 c = mGrid.cellOf(p);
        return mGrid.inGrid(c.x, c.y) && passable(mGrid.index(uint32_t(c.x), uint32_t(c.y)));
    }
    /// The directed costs of `tile`, or null where every direction costs cost().
    const DirectedCosts* directed(uint32_t tile) const { return mDirected[tile].get(); }
    /// The agents counted in the cell under world point `p` at the last
    /// density splat: how many, and their summed velocity.
    void crowdAt(glm::vec2 p, float& count, glm::vec2& velocity) const;
    /// The largest cost of leaving `cell` in any direction.
    float highestCost(uint32_t cell) const;

    void addHazard(const Hazard& hazard) { mHazards.push_back(hazard); }
    /// Drops the hazards expired at `now`, appending the cells they covered.
    void expireHazards(double now, std::vector<CellRect>& freed);
    uint32_t hazardCount() const { return uint32_t(mHazards.size()); }
    /// The active hazard containing `p`, or null.
    const Hazard* hazardAt(glm::vec2 p) const;
    /// The cells a hazard makes impassable.
    CellRect hazardCells(const Hazard& hazard) const;

    /// Recounts `tile`'s samples: the agents binned in it (how many, their
    /// summed velocity), and the intended directions (unit, or zero) of
    /// those and of the agents of the tiles around whose way ahead crosses
    /// it. Writes only this tile's samples.
    void recountTile(uint32_t tile, const AgentBins& bins, std::span<const glm::vec3> positions,
                     std::span<const glm::vec2> velocities, std::span<const glm::vec2> intentions);
    /// Whether `tile` holds samples (agents, or wishes to walk through it).
    bool hasSamples(uint32_t tile) const { return mSamples[tile] != nullptr; }
    /// Agents per square metre around `p` (3 x 3 cells) that want to walk
    /// against unit `direction`, here or a few metres on.
    /// (Inline, as passableAt: every walking agent asks once a step.)
    float oncoming(glm::vec2 p, glm::vec2 direction) const {
        // Over about 3 x 3 metres at least: the cell alone where cells are
        // that large (the content map's 4 m), else the 3 x 3 cells around it.
        constexpr int32_t n = int32_t(NavGrid::kTileCells);
        const glm::ivec2 c = mGrid.cellOf(p);
        const int32_t reach = mGrid.cellSize() >= 3.0f ? 0 : 1;
        float against = 0.0f;
        for (int32_t j = c.y - reach; j <= c.y + reach; ++j)
            for (int32_t i = c.x - reach; i <= c.x + reach; ++i) {
                if (!mGrid.inGrid(i, j)) continue;
                const Samples* samples = mSamples[mGrid.tileOf(uint32_t(i), uint32_t(j))].get();
                if (!samples) continue;
                const auto& intent = samples->cells[size_t((j % n) * n + i % n)].intent;
                against += std::max(direction.x, 0.0f) * intent[kMinusX] + std::max(-direction.x, 0.0f) * intent[kPlusX] +
                           std::max(direction.y, 0.0f) * intent[kMinusZ] + std::max(-direction.y, 0.0f) * intent[kPlusZ];
            }
        const float side = float(2 * reach + 1) * mGrid.cellSize();
        return against / (side * side);
    }
    /// Recomputes every cell of `tiles` (ascending, distinct) and records
    /// what changed.
    void recomputeTiles(std::span<const uint32_t> tiles, CostChanges& changes, uint32_t threads);
    /// The tiles a cell rectangle touches, ascending.
    std::vector<uint32_t> tilesOf(const CellRect& cells) const;
    size_t bytes() const;

private:
    /// Agents counted into one tile's cells (row by row).
    struct Samples {
        struct Cell {
            uint16_t count = 0;        ///< agents standing in it
            glm::vec2 velocity{0.0f};  ///< their summed velocity
            /// Per direction (Direction order), how many want to walk that
            /// way, here or a few metres on: the sum of their intended unit
            /// directions' components.
            std::array<float, 4> intent{};
        };
        std::array<Cell, NavGrid::kTileCells * NavGrid::kTileCells> cells{};
    };

    struct CrowdWindow;

    bool recomputeTile(uint32_t tile, std::vector<uint32_t>& raised);
    /// Fills `window` with the box-filtered crowd around `tile`.
    void gatherCrowd(uint32_t tile, CrowdWindow& window) const;
    /// How much the crowd adds to the cost of leaving cell (i, j) of the
    /// window in direction d, as a multiple of the ground cost.
    float crowdingCost(const CrowdWindow& window, int32_t i, int32_t j, int d) const;
    /// Density of `count` agents over 3 x 3 cells, 0 at densityMin to 1 at densityMax.
    float densityFraction(float count) const;

    const NavGrid& mGrid;
    float mDensityMin, mDensityRange, mSlowest, mFlowSpeed;
    int32_t mLaneAhead, mLaneSide; ///< the keep-right look, in cells
    int32_t mAnticipation;         ///< cells ahead an agent's intention is counted in
    std::vector<float> mCost;
    std::vector<std::unique_ptr<Samples>> mSamples;        ///< per tile, where agents are
    std::vector<std::unique_ptr<DirectedCosts>> mDirected; ///< per tile, where the crowd raises costs
    std::vector<Hazard> mHazards;
};

} // namespace tessera::crowd
