#pragma once
/// @file MinMaxPyramid.h
/// Minimum and maximum height per patch and per 2x2, 4x4, ... block of
/// patches: the true displaced bounds the culler tests.

#include "tessera/scene/Aabb.h"
#include "tessera/terrain/PatchGrid.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <utility>
#include <vector>

namespace tessera::terrain {

/// Level 0 holds one (min, max) per patch, taken over every sample the
/// patch's surface interpolates (PatchGrid::patchSamples), so the bounds hold
/// the displaced surface exactly at any tessellation level. Level k+1 merges
/// 2x2 cells of level k (odd sizes round up; the last cell merges what
/// exists); the top level is a single cell.
class MinMaxPyramid {
public:
    /// Builds every level from `field`. Keeps references to both.
    MinMaxPyramid(const HeightField& field, const PatchGrid& grid);

    uint32_t levelCount() const { return static_cast<uint32_t>(mLevels.size()); }
    /// Cells per side at `level` (level 0: patches per side).
    uint32_t levelSize(uint32_t level) const { return mLevels[level].size; }
    /// (min, max) height in metres of cell (x, z) at `level`.
    std::pair<float, float> minMax(uint32_t level, uint32_t x, uint32_t z) const;
    /// World-space box of cell (x, z) at `level`: its XZ extent and height range.
    scene::Aabb cellBounds(uint32_t level, uint32_t x, uint32_t z) const;
    /// World-space box of one patch (level 0).
    scene::Aabb patchBounds(uint32_t patch) const;

    /// The crowd's horizon grid (lod::LodView::occluders): the lowest height
    /// of each cell of the finest level with at most `maxCellsPerSide`
    /// cells a side, row by row into `lowest`; a cell reaching past the
    /// terrain's edge occludes nothing (lowest -1e30). Returns its min
    /// corner (x, z), cell side and cells per side, as
    /// shader::CrowdLodParams::occluder; all 0 (and `lowest` empty) where
    /// the patches are not square.
    glm::vec4 horizonGrid(uint32_t maxCellsPerSide, std::vector<float>& lowest) const;

    /// Recomputes level 0 for the patches in the inclusive patch rectangle and
    /// every level above them (after a splat changed heights there).
    void update(const SampleRect& patches);

private:
    struct Level {
        uint32_t size = 0;
        std::vector<std::pair<float, float>> cells;
    };
    void computePatch(uint32_t x, uint32_t z);
    void mergeCell(uint32_t level, uint32_t x, uint32_t z);

    const HeightField& mField;
    const PatchGrid& mGrid;
    std::vector<Level> mLevels;
};

} // namespace tessera::terrain
