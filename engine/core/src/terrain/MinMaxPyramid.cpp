#include "tessera/terrain/MinMaxPyramid.h"

#include <algorithm>
#include <cassert>

namespace tessera::terrain {

MinMaxPyramid::MinMaxPyramid(const HeightField& field, const PatchGrid& grid) : mField(field), mGrid(grid) {
    // Sizes halve, rounding up, down to one cell: ceil(log2(P)) + 1 levels.
    uint32_t size = grid.patchesPerSide();
    for (;;) {
        mLevels.push_back({size, std::vector<std::pair<float, float>>(size_t(size) * size)});
        if (size == 1) break;
        size = (size + 1) / 2;
    }
    update({0, 0, grid.patchesPerSide() - 1, grid.patchesPerSide() - 1});
}

std::pair<float, float> MinMaxPyramid::minMax(uint32_t level, uint32_t x, uint32_t z) const {
    assert(level < levelCount() && x < levelSize(level) && z < levelSize(level));
    return mLevels[level].cells[size_t(z) * mLevels[level].size + x];
}

scene::Aabb MinMaxPyramid::cellBounds(uint32_t level, uint32_t x, uint32_t z) const {
    const auto [lo, hi] = minMax(level, x, z);
    // The cell covers patches [x << level, (x + 1) << level) clipped to the
    // grid. Corners use float(patch index) * patchSize, as PatchGrid does, so a
    // child's box is never a hair outside its parent's and culling a parent
    // decides exactly what testing its children would.
    const uint32_t p = mGrid.patchesPerSide();
    const glm::vec2 size = mGrid.patchSize();
    const glm::vec2 world = mField.worldSize();
    const uint32_t x0 = x << level, z0 = z << level;
    const uint32_t x1 = std::min((x + 1) << level, p), z1 = std::min((z + 1) << level, p);
    const glm::vec2 cornerLo = glm::min(glm::vec2(float(x0), float(z0)) * size, world);
    const glm::vec2 cornerHi = glm::min(glm::vec2(float(x1), float(z1)) * size, world);
    return scene::Aabb::fromMinMax({cornerLo.x, lo, cornerLo.y}, {cornerHi.x, hi, cornerHi.y});
}

scene::Aabb MinMaxPyramid::patchBounds(uint32_t patch) const {
    const uint32_t p = mGrid.patchesPerSide();
    return cellBounds(0, patch % p, patch / p);
}

glm::vec4 MinMaxPyramid::horizonGrid(uint32_t maxCellsPerSide, std::vector<float>& lowest) const {
    lowest.clear();
    const glm::vec2 size = mGrid.patchSize();
    if (size.x != size.y || maxCellsPerSide == 0) return glm::vec4(0.0f);
    uint32_t level = 0;
    while (level + 1 < levelCount() && levelSize(level) > maxCellsPerSide) ++level;
    const uint32_t n = levelSize(level);
    if (n > maxCellsPerSide) return glm::vec4(0.0f);
    const uint32_t patches = mGrid.patchesPerSide();
    lowest.resize(size_t(n) * n);
    for (uint32_t z = 0; z < n; ++z)
        for (uint32_t x = 0; x < n; ++x) {
            // A cell past the last patch holds ground only over part of it.
            const bool whole = ((x + 1) << level) <= patches && ((z + 1) << level) <= patches;
            lowest[size_t(z) * n + x] = whole ? minMax(level, x, z).first : -1e30f;
        }
    return glm::vec4(0.0f, 0.0f, size.x * float(1u << level), float(n));
}

void MinMaxPyramid::update(const SampleRect& patches) {
    if (patches.empty()) return;
    const uint32_t p = mGrid.patchesPerSide();
    const uint32_t x0 = patches.i0, z0 = patches.j0;
    const uint32_t x1 = std::min(patches.i1, p - 1), z1 = std::min(patches.j1, p - 1);
    for (uint32_t z = z0; z <= z1; ++z)
        for (uint32_t x = x0; x <= x1; ++x) computePatch(x, z);
    // Only the ancestors of changed patches change: the rectangle shifted down
    // by the level at each step up.
    for (uint32_t level = 1; level < levelCount(); ++level)
        for (uint32_t z = z0 >> level; z <= z1 >> level; ++z)
            for (uint32_t x = x0 >> level; x <= x1 >> level; ++x) mergeCell(level, x, z);
}

void MinMaxPyramid::computePatch(uint32_t x, uint32_t z) {
    // The samples the patch's bilinear surface interpolates; interpolation
    // never leaves their range, so the box holds the surface at any level.
    const SampleRect s = mGrid.patchSamples(z * mGrid.patchesPerSide() + x);
    mLevels[0].cells[size_t(z) * mLevels[0].size + x] = mField.minMaxHeight(s.i0, s.j0, s.i1, s.j1);
}

void MinMaxPyramid::mergeCell(uint32_t level, uint32_t x, uint32_t z) {
    const Level& below = mLevels[level - 1];
    std::pair<float, float> merged = below.cells[size_t(2 * z) * below.size + 2 * x];
    // Odd sizes: the last row and column have fewer children.
    for (uint32_t cz = 2 * z; cz < std::min(2 * z + 2, below.size); ++cz)
        for (uint32_t cx = 2 * x; cx < std::min(2 * x + 2, below.size); ++cx) {
            const auto& child = below.cells[size_t(cz) * below.size + cx];
            merged.first = std::min(merged.first, child.first);
            merged.second = std::max(merged.second, child.second);
        }
    mLevels[level].cells[size_t(z) * mLevels[level].size + x] = merged;
}

} // namespace tessera::terrain
