#include "tessera/crowd/NavGrid.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::crowd {
namespace {

// The steepest gradient of the bilinear surface over quad (qi, qj) of the
// height field. Each partial derivative of a bilinear patch is linear in the
// other coordinate, so |grad h| is largest at a corner, where it is made of
// the two edges meeting there.
float quadSlope(const terrain::HeightField& field, uint32_t qi, uint32_t qj, float inverseSpacing) {
    const float h00 = field.sampleHeight(qi, qj), h10 = field.sampleHeight(qi + 1, qj);
    const float h01 = field.sampleHeight(qi, qj + 1), h11 = field.sampleHeight(qi + 1, qj + 1);
    const float dx0 = h10 - h00, dx1 = h11 - h01, dz0 = h01 - h00, dz1 = h11 - h10;
    const float steepest = std::max(std::max(dx0 * dx0 + dz0 * dz0, dx0 * dx0 + dz1 * dz1),
                                    std::max(dx1 * dx1 + dz0 * dz0, dx1 * dx1 + dz1 * dz1));
    return std::sqrt(steepest) * inverseSpacing;
}

} // namespace

NavGrid::NavGrid(const terrain::Terrain& terrain, float cellSize, float maxSlopeDegrees, float speedAtLimit)
    : mCellSize(cellSize), mMaxSlope(std::tan(glm::radians(maxSlopeDegrees))), mSpeedAtLimit(speedAtLimit) {
    mWorldSize = terrain.field().worldSize();
    // Whole cells only: the strip narrower than a cell at the far edges is
    // left out (impassable), so every cell lies on the terrain.
    mWidth = std::max(1u, uint32_t(mWorldSize.x / cellSize));
    mHeight = std::max(1u, uint32_t(mWorldSize.y / cellSize));
    mTilesX = (mWidth + kTileCells - 1) / kTileCells;
    mTilesZ = (mHeight + kTileCells - 1) / kTileCells;
    mTerrainCost.assign(cellCount(), kImpassable);
    computeCells(terrain.field(), {0, 0, int32_t(mWidth) - 1, int32_t(mHeight) - 1}, 0);
}

glm::ivec2 NavGrid::cellOf(glm::vec2 p) const {
    return {int32_t(std::floor(p.x / mCellSize)), int32_t(std::floor(p.y / mCellSize))};
}

CellRect NavGrid::tileCells(uint32_t tile) const {
    const int32_t ti = int32_t(tile % mTilesX), tj = int32_t(tile / mTilesX);
    const int32_t n = int32_t(kTileCells);
    return {ti * n, tj * n, std::min((ti + 1) * n, int32_t(mWidth)) - 1, std::min((tj + 1) * n, int32_t(mHeight)) - 1};
}

CellRect NavGrid::cellsTouching(glm::vec2 min, glm::vec2 max) const {
    const glm::ivec2 a = cellOf(min), b = cellOf(max);
    return {std::max(a.x, 0), std::max(a.y, 0), std::min(b.x, int32_t(mWidth) - 1),
            std::min(b.y, int32_t(mHeight) - 1)};
}

bool NavGrid::walkable(glm::vec2 p) const {
    const glm::ivec2 c = cellOf(p);
    return inGrid(c.x, c.y) && std::isfinite(mTerrainCost[index(uint32_t(c.x), uint32_t(c.y))]);
}

float NavGrid::speedFactor(uint32_t i) const {
    const float cost = mTerrainCost[i];
    return std::isfinite(cost) ? 1.0f / cost : 0.0f;
}

float NavGrid::costFromSlope(float slope) const {
    if (!(slope <= mMaxSlope)) return kImpassable;
    const float t = slope / mMaxSlope;
    return 1.0f / (1.0f - (1.0f - mSpeedAtLimit) * t * t);
}

void NavGrid::computeCells(const terrain::HeightField& field, const CellRect& cells, uint32_t threads) {
    if (cells.empty()) return;
    const float spacing = field.scale().horizontalSpacing;
    const float inverseSpacing = 1.0f / spacing;
    const int32_t lastQuadI = int32_t(field.width()) - 2, lastQuadJ = int32_t(field.height()) - 2;
    const uint32_t rows = uint32_t(cells.j1 - cells.j0 + 1);
    core::parallelFor(rows, threads, [&](uint32_t row) {
        const int32_t j = cells.j0 + int32_t(row);
        // One quad of margin on every side: HeightField::normalAt's taps
        // reach one spacing beyond the point.
        const int32_t qj0 = std::max(int32_t(std::floor(float(j) * mCellSize * inverseSpacing)) - 1, 0);
        const int32_t qj1 = std::min(int32_t(std::ceil(float(j + 1) * mCellSize * inverseSpacing)), lastQuadJ);
        for (int32_t i = cells.i0; i <= cells.i1; ++i) {
            const int32_t qi0 = std::max(int32_t(std::floor(float(i) * mCellSize * inverseSpacing)) - 1, 0);
            const int32_t qi1 = std::min(int32_t(std::ceil(float(i + 1) * mCellSize * inverseSpacing)), lastQuadI);
            float slope = 0.0f;
            for (int32_t qj = qj0; qj <= qj1; ++qj)
                for (int32_t qi = qi0; qi <= qi1; ++qi)
                    slope = std::max(slope, quadSlope(field, uint32_t(qi), uint32_t(qj), inverseSpacing));
            mTerrainCost[index(uint32_t(i), uint32_t(j))] = costFromSlope(slope);
        }
    });
}

CellRect NavGrid::refresh(const terrain::Terrain& terrain, glm::vec2 min, glm::vec2 max) {
    // A changed sample moves the quads around it, which reach one more
    // spacing into the cells beside them.
    const float reach = 2.0f * terrain.field().scale().horizontalSpacing;
    const CellRect cells = cellsTouching(min - reach, max + reach);
    computeCells(terrain.field(), cells, 1);
    return cells;
}

} // namespace tessera::crowd
