#pragma once
// Internal: the grid that finds an agent's neighbours.

#include "tessera/crowd/FloorToInt.h"
#include "tessera/crowd/NavGrid.h"

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tessera::crowd {

/// A neighbour found by NeighbourGrid::nearest().
struct NearAgent {
    uint32_t agent = 0;
    float distance2 = 0.0f; ///< squared distance
    glm::vec2 offset{0.0f}; ///< its position less the query point
};

/// The agents as the crowd's tile bins hold them (AgentBins), which is what
/// NeighbourGrid is built from: tile t's agents are order[start[t]] ..
/// order[start[t + 1] - 1]; an agent's tile is that of the navigation cell
/// under it, clamped to the grid (`cellSize` metres from world (0, 0),
/// `width` by `height` cells, NavGrid::kTileCells a side to a tile).
struct TileAgents {
    std::span<const uint32_t> order;
    std::span<const uint32_t> start;
    std::span<const uint32_t> occupied; ///< tiles holding agents, ascending
    float cellSize = 1.0f;
    uint32_t width = 0, height = 0;
};

/// Each tile's agents sorted into a grid of square cells inside the tile,
/// their positions stored cell by cell, so a query reads a few short runs.
/// Built from the tile bins, each tile on its own (in parallel, no shared
/// counters), so it costs one pass over the agents. A tile holding few
/// agents gets fewer cells, so the cells never outnumber its agents.
///
/// What a query returns does not depend on the cell size or the order the
/// cells keep agents in: nearest() breaks equal distances by agent index,
/// and forEachNear's callers sum in an order of their own (Crowd::separate).
class NeighbourGrid {
public:
    /// Sorts the agents of `tiles` (positions: world XZ from x and z) into
    /// cells of about `cellSize` metres, on `threads` threads.
    void build(std::span<const glm::vec3> positions, const TileAgents& tiles, float cellSize, uint32_t threads);

    /// Calls f(agent, position) for every agent whose cell lies within
    /// `radius` of `p` along both axes (a superset of those within `radius`),
    /// with its XZ position as of build(); each agent once.
    template <class F>
    void forEachNear(glm::vec2 p, float radius, F&& f) const {
        forEachRun(p, radius, [&](uint32_t first, uint32_t end) {
            for (uint32_t s = first; s < end; ++s) f(mAgent[s], mPosition[s]);
        });
    }

    /// Cells, for marks kept beside the grid: 0 .. cellCount() - 1.
    uint32_t cellCount() const { return uint32_t(mCellStart.size()); }
    /// The cell an agent that stood at `p` at build() was sorted into.
    uint32_t cellOf(glm::vec2 p) const {
        const uint32_t tx = tileOf(p.x, mWidth), tz = tileOf(p.y, mHeight);
        const TileCells& t = mTiles[tz * mTilesX + tx];
        const glm::vec2 origin = glm::vec2(float(tx), float(tz)) * mTileSize;
        const int32_t last = int32_t(t.side) - 1;
        const int32_t cx = std::clamp(floorToInt((p.x - origin.x) * t.inverseCell), 0, last);
        const int32_t cz = std::clamp(floorToInt((p.y - origin.y) * t.inverseCell), 0, last);
        return t.first + uint32_t(cz) * t.side + uint32_t(cx);
    }
    /// Whether marked(cell) holds for any cell forEachNear(p, radius) reads.
    template <class F>
    bool anyCellNear(glm::vec2 p, float radius, F&& marked) const {
        bool any = false;
        forEachCellRow(p, radius, [&](uint32_t first, uint32_t last) {
            for (uint32_t c = first; c <= last; ++c) any |= marked(c);
        });
        return any;
    }

    /// The up to `count` (at most kMaxNearest) agents nearest `p` within
    /// `radius`, `self` left out, nearest first (equal distances by agent
    /// index), into `out`; returns how many. Looks within `closeRadius`
    /// first, and over the rest of `radius` only when that found fewer than
    /// `count` (closeRadius >= radius: one look).
    uint32_t nearest(glm::vec2 p, uint32_t self, float closeRadius, float radius, uint32_t count,
                     NearAgent* out) const;
    static constexpr uint32_t kMaxNearest = 16;

    /// Bytes held that grow with the agents (cells and slots), and with the
    /// navigation tiles (for the memory figures).
    size_t agentBytes() const;
    size_t tileBytes() const;

private:
    // Where tile t's cells are: mCellStart[first] .. mCellStart[first + side * side]
    // are the slots where its cells begin, row by row (and where the last
    // ends); `side` cells of `cell` metres across. side 0: no agents.
    struct TileCells {
        uint32_t first = 0;
        uint32_t side = 0;
        float inverseCell = 1.0f;
    };

    // Calls f(first, end) for each run of slots holding one row of the cells
    // within `radius` of `p` along both axes, tile by tile.
    template <class F>
    void forEachRun(glm::vec2 p, float radius, F&& f) const {
        forEachCellRow(p, radius, [&](uint32_t first, uint32_t last) { f(mCellStart[first], mCellStart[last + 1]); });
    }
    // Calls f(first, last) for each row of the cells within `radius` of `p`
    // along both axes, tile by tile: cells first .. last (inclusive).
    template <class F>
    void forEachCellRow(glm::vec2 p, float radius, F&& f) const {
        // Tiles found as the bins found them (the navigation cell, clamped,
        // then its tile), so the same float rounding puts an agent and a
        // query around it in the same tile.
        const uint32_t tx0 = tileOf(p.x - radius, mWidth), tx1 = tileOf(p.x + radius, mWidth);
        const uint32_t tz0 = tileOf(p.y - radius, mHeight), tz1 = tileOf(p.y + radius, mHeight);
        for (uint32_t tz = tz0; tz <= tz1; ++tz)
            for (uint32_t tx = tx0; tx <= tx1; ++tx) {
                const TileCells& t = mTiles[tz * mTilesX + tx];
                if (t.side == 0) continue;
                // The box relative to the tile, in its cells (clamped: agents
                // outside the grid were binned into its edge tiles' edge cells).
                const glm::vec2 origin = glm::vec2(float(tx), float(tz)) * mTileSize;
                const int32_t last = int32_t(t.side) - 1;
                const int32_t cx0 = std::clamp(floorToInt((p.x - radius - origin.x) * t.inverseCell), 0, last);
                const int32_t cx1 = std::clamp(floorToInt((p.x + radius - origin.x) * t.inverseCell), 0, last);
                const int32_t cz0 = std::clamp(floorToInt((p.y - radius - origin.y) * t.inverseCell), 0, last);
                const int32_t cz1 = std::clamp(floorToInt((p.y + radius - origin.y) * t.inverseCell), 0, last);
                uint32_t row = t.first + uint32_t(cz0) * t.side;
                for (int32_t cz = cz0; cz <= cz1; ++cz, row += t.side) f(row + uint32_t(cx0), row + uint32_t(cx1));
            }
    }

    uint32_t tileOf(float v, uint32_t cells) const {
        return uint32_t(std::clamp(floorToInt(v * mInverseCell), 0, int32_t(cells) - 1)) / NavGrid::kTileCells;
    }

    float mInverseCell = 1.0f, mTileSize = 1.0f;
    uint32_t mWidth = 0, mHeight = 0, mTilesX = 0, mTilesZ = 0;
    std::vector<TileCells> mTiles;     ///< per tile of the grid
    std::vector<uint32_t> mCellStart;  ///< per cell of the occupied tiles, and one past each tile's last
    std::vector<uint32_t> mAgent;      ///< slot -> agent
    std::vector<glm::vec2> mPosition;  ///< slot -> XZ position
};

} // namespace tessera::crowd
