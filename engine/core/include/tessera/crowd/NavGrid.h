#pragma once
/// @file NavGrid.h
/// The crowd's navigation grid over the terrain: cell geometry, tiles, and
/// the cost of walking on the ground itself (slope), impassable where it is
/// too steep.

#include "tessera/crowd/FloorToInt.h"
#include "tessera/terrain/Terrain.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec2.hpp>

namespace tessera::crowd {

/// An inclusive rectangle of cells, [i0, i1] x [j0, j1]; empty when i0 > i1.
struct CellRect {
    int32_t i0 = 1, j0 = 1, i1 = 0, j1 = 0;
    bool empty() const { return i0 > i1 || j0 > j1; }
};

/// Square cells of cellSize() metres covering the terrain from world (0, 0),
/// grouped into tiles of kTileCells x kTileCells (the unit of the field
/// solver, of density splatting and of the crowd's bounds hierarchy).
///
/// Terrain cost is the cost per metre of walking on the ground: 1 on the
/// flat, rising as 1 / speedFactor with slope, infinite where the slope an
/// agent measures (Terrain::normalAt's central differences) anywhere in the
/// cell is steeper than the limit. Positions outside the terrain are
/// impassable.
class NavGrid {
public:
    static constexpr uint32_t kTileCells = 16;
    static constexpr float kImpassable = std::numeric_limits<float>::infinity();

    /// Covers `terrain` with cells of `cellSize` metres; see CrowdSettings for
    /// the slope parameters. Reads the terrain; keeps no reference to it.
    NavGrid(const terrain::Terrain& terrain, float cellSize, float maxSlopeDegrees, float speedAtLimit);

    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }
    uint32_t cellCount() const { return mWidth * mHeight; }
    float cellSize() const { return mCellSize; }
    uint32_t tilesX() const { return mTilesX; }
    uint32_t tilesZ() const { return mTilesZ; }
    uint32_t tileCount() const { return mTilesX * mTilesZ; }
    /// World extent covered by the terrain (cells beyond it are impassable).
    glm::vec2 worldSize() const { return mWorldSize; }

    /// Cell coordinates of world point `p` (may lie outside the grid).
    /// (Inline, by the inverse of the cell size: every agent looks up cells
    /// many times a step.)
    glm::ivec2 cellOf(glm::vec2 p) const {
        return {floorToInt(p.x * mInverseCellSize), floorToInt(p.y * mInverseCellSize)};
    }
    bool inGrid(int32_t i, int32_t j) const { return i >= 0 && j >= 0 && uint32_t(i) < mWidth && uint32_t(j) < mHeight; }
    uint32_t index(uint32_t i, uint32_t j) const { return j * mWidth + i; }
    glm::vec2 cellCenter(uint32_t i, uint32_t j) const { return (glm::vec2(float(i), float(j)) + 0.5f) * mCellSize; }
    /// Tile holding cell (i, j).
    uint32_t tileOf(uint32_t i, uint32_t j) const { return (j / kTileCells) * mTilesX + i / kTileCells; }
    /// Cells of tile `tile`, clipped to the grid.
    CellRect tileCells(uint32_t tile) const;
    /// The cells a world rectangle touches, clipped to the grid.
    CellRect cellsTouching(glm::vec2 min, glm::vec2 max) const;

    /// Terrain cost of cell `index` (kImpassable when too steep).
    float terrainCost(uint32_t index) const { return mTerrainCost[index]; }
    /// Whether world point `p` is on walkable ground of the grid.
    bool walkable(glm::vec2 p) const;
    /// Walking speed on cell `index` relative to flat ground: (0, 1], 0 when impassable.
    float speedFactor(uint32_t index) const {
        const float cost = mTerrainCost[index];
        return std::isfinite(cost) ? 1.0f / cost : 0.0f;
    }

    /// Recomputes the cells whose slope can have changed after the terrain
    /// changed inside world rectangle [min, max] (a crater). Returns them.
    CellRect refresh(const terrain::Terrain& terrain, glm::vec2 min, glm::vec2 max);

private:
    void computeCells(const terrain::HeightField& field, const CellRect& cells, uint32_t threads);
    float costFromSlope(float slope) const;

    uint32_t mWidth = 0, mHeight = 0, mTilesX = 0, mTilesZ = 0;
    float mCellSize = 1.0f;
    float mInverseCellSize = 1.0f;
    float mMaxSlope = 1.0f;
    float mSpeedAtLimit = 0.35f;
    glm::vec2 mWorldSize{0.0f};
    std::vector<float> mTerrainCost;
};

} // namespace tessera::crowd
