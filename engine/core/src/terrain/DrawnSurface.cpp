#include "tessera/terrain/DrawnSurface.h"

#include "tessera/terrain/Terrain.h"
#include "tessera/tessellator/PatternLocator.h"
#include "tessera/tessellator/Tessellator.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace tessera::terrain {

DrawnSurface::DrawnSurface(const Terrain& terrain) : mTerrain(terrain), mPatches(terrain.grid().patchCount()) {
    update({.mode = TerrainMode::LowRes}, {}, 1.0f);
}

DrawnSurface::~DrawnSurface() = default;

void DrawnSurface::update(const TessellationSettings& settings, const TessView& view, float backendMaxLevel) {
    mHeightField = false;
    mLevels = computeTessLevels(mTerrain, settings, view, backendMaxLevel);
    // A crater changes heights, not patterns; rare enough to rebuild all.
    const bool reshaped = mTerrain.revision() != mRevision;
    mRevision = mTerrain.revision();
    for (uint32_t p = 0; p < mPatches.size(); ++p) {
        Patch& patch = mPatches[p];
        const std::array<float, 6> factors = patchFactors(p);
        if (patch.built && factors == patch.factors && !reshaped) continue;
        patch.factors = factors;
        patch.built = std::make_unique<std::once_flag>();
        patch.locator.reset();
        patch.heights.clear();
    }
}

std::array<float, 6> DrawnSurface::patchFactors(uint32_t patch) const {
    const PatchGrid& grid = mTerrain.grid();
    const std::array<uint32_t, 4> edges = grid.patchEdges(patch);
    const std::array<float, 2> inner = innerLevels(mLevels, grid, patch);
    return {mLevels.edges[edges[0]],
            mLevels.edges[edges[1]],
            mLevels.edges[edges[2]],
            mLevels.edges[edges[3]],
            inner[0],
            inner[1]};
}

const DrawnSurface::Patch& DrawnSurface::built(uint32_t index) const {
    Patch& patch = mPatches[index];
    std::call_once(*patch.built, [this, &patch, index] {
        tessellator::TessFactors factors;
        std::copy_n(patch.factors.begin(), 4, factors.outer.begin());
        std::copy_n(patch.factors.begin() + 4, 2, factors.inner.begin());
        // The terrain's spacing on every backend (the control stage's
        // fractional_odd_spacing, the emulated tessellator's patterns).
        patch.locator = std::make_unique<tessellator::PatternLocator>(tessellator::Tessellator::tessellate(
            tessellator::Domain::Quad, tessellator::Partitioning::FractionalOdd, factors));
        // A vertex where the evaluation stages put it (terrainPatchPoint:
        // (corner + uv) * size), at the height field's height there: once
        // per point, where a patch's agents would read three each.
        const PatchGrid& grid = mTerrain.grid();
        const glm::vec2 corner(float(index % grid.patchesPerSide()), float(index / grid.patchesPerSide()));
        patch.heights.reserve(patch.locator->patch().uv.size());
        for (const glm::vec2 uv : patch.locator->patch().uv) {
            const glm::vec2 xz = (corner + uv) * grid.patchSize();
            patch.heights.push_back(mTerrain.heightAt(xz.x, xz.y));
        }
    });
    return patch;
}

float DrawnSurface::heightAt(float x, float z) const {
    if (mHeightField) return mTerrain.heightAt(x, z);
    const PatchGrid& grid = mTerrain.grid();
    const uint32_t side = grid.patchesPerSide();
    const glm::vec2 size = grid.patchSize();
    const glm::vec2 at = glm::vec2(x, z) / size;
    const glm::vec2 cell = glm::clamp(glm::floor(at), glm::vec2(0.0f), glm::vec2(float(side - 1)));
    const Patch& patch = built(uint32_t(cell.y) * side + uint32_t(cell.x));
    if (patch.locator->empty()) return mTerrain.heightAt(x, z);
    const tessellator::PatternLocator::Hit hit = patch.locator->locate(at - cell);
    return hit.weights.x * patch.heights[hit.corners[0]] + hit.weights.y * patch.heights[hit.corners[1]] +
           hit.weights.z * patch.heights[hit.corners[2]];
}

} // namespace tessera::terrain
