#include "Navigation.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::crowd {
namespace {

void sortUnique(std::vector<uint32_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

} // namespace

Navigation::Navigation(const terrain::Terrain& terrain, const CrowdSettings& settings,
                       std::span<const GoalGroup> goals)
    : mSettings(settings), mGrid(terrain, settings.cellSize, settings.maxSlopeDegrees, settings.slopeSpeedAtLimit),
      mCost(mGrid, settings), mSolver(mGrid) {
    for (const GoalGroup& goal : goals) mFields.push_back(std::make_unique<PotentialField>(mGrid, goal.region));
}

void Navigation::solveAll() {
    for (auto& field : mFields) field->activateGoalTiles();
    settle();
}

void Navigation::settle() {
    std::vector<PotentialField*> fields;
    for (auto& field : mFields) fields.push_back(field.get());
    // A wavefront crosses each tile a few times; the cap only guards against
    // a solve that would not settle.
    mSolver.solve(fields, mCost, 64 * mGrid.tileCount(), mSettings.threads);
}

uint32_t Navigation::solve() {
    std::vector<PotentialField*> fields;
    for (auto& field : mFields) fields.push_back(field.get());
    const uint32_t perField = std::max(FieldSolver::kTilesPerPass / 4, mSettings.fieldTileBudget / groupCount());
    return mSolver.solve(fields, mCost, perField, mSettings.threads);
}

uint32_t Navigation::activeTiles() const {
    uint32_t n = 0;
    for (const auto& field : mFields) n += field->activeTileCount();
    return n;
}

void Navigation::apply(const CostChanges& changes) {
    if (changes.empty()) return;
    for (auto& field : mFields) {
        field->invalidateDependents(changes.raised, [this](uint32_t cell) { return mCost.highestCost(cell); });
        for (uint32_t tile : changes.tiles) field->activateByContent(tile);
    }
}

void Navigation::recompute(const std::vector<uint32_t>& tiles) {
    CostChanges changes;
    mCost.recomputeTiles(tiles, changes, mSettings.threads);
    apply(changes);
}

Hazard Navigation::addCrater(const terrain::Terrain& terrain, const terrain::CraterSplat& splat, double now) {
    const glm::vec2 reach(splat.radius);
    const CellRect ground = mGrid.refresh(terrain, splat.center - reach, splat.center + reach);
    const Hazard hazard{splat.center, splat.radius + mSettings.hazardMargin, now + mSettings.hazardSeconds};
    mCost.addHazard(hazard);
    std::vector<uint32_t> tiles = mCost.tilesOf(ground);
    const std::vector<uint32_t> covered = mCost.tilesOf(mCost.hazardCells(hazard));
    tiles.insert(tiles.end(), covered.begin(), covered.end());
    sortUnique(tiles);
    recompute(tiles);
    return hazard;
}

void Navigation::expireHazards(double now) {
    std::vector<CellRect> freed;
    mCost.expireHazards(now, freed);
    if (freed.empty()) return;
    std::vector<uint32_t> tiles;
    for (const CellRect& cells : freed) {
        const std::vector<uint32_t> t = mCost.tilesOf(cells);
        tiles.insert(tiles.end(), t.begin(), t.end());
    }
    sortUnique(tiles);
    recompute(tiles);
}

void Navigation::updateDensity(const AgentBins& bins, std::span<const glm::vec3> positions,
                               std::span<const glm::vec2> velocities, std::span<const glm::vec2> intentions) {
    // Recount the tiles agents stand on or may anticipate walking into (the
    // tiles around), and those that held samples at the last splat (they
    // may have emptied).
    const uint32_t tx = mGrid.tilesX(), tz = mGrid.tilesZ();
    auto around = [&](std::span<const uint32_t> centres, std::vector<uint32_t>& out) {
        for (uint32_t t : centres) {
            const uint32_t x = t % tx, z = t / tx;
            for (uint32_t nz = z ? z - 1 : 0; nz <= std::min(z + 1, tz - 1); ++nz)
                for (uint32_t nx = x ? x - 1 : 0; nx <= std::min(x + 1, tx - 1); ++nx) out.push_back(nz * tx + nx);
        }
    };
    std::vector<uint32_t> recount(mDensityTiles);
    around(bins.occupiedTiles(), recount);
    sortUnique(recount);
    // Each tile's recount writes only that tile's samples.
    core::parallelFor(uint32_t(recount.size()), mSettings.threads, [&](uint32_t k) {
        mCost.recountTile(recount[k], bins, positions, velocities, intentions);
    });
    // The costs that can have changed: around the tiles that held samples
    // before or hold them now (the box filter and the look-ahead reach one
    // tile).
    std::vector<uint32_t> changed(mDensityTiles);
    mDensityTiles.clear();
    for (uint32_t t : recount)
        if (mCost.hasSamples(t)) mDensityTiles.push_back(t);
    changed.insert(changed.end(), mDensityTiles.begin(), mDensityTiles.end());
    sortUnique(changed);
    std::vector<uint32_t> tiles;
    around(changed, tiles);
    sortUnique(tiles);
    recompute(tiles);
}

glm::vec2 Navigation::escapeDirection(glm::vec2 p) const {
    if (const Hazard* hazard = mCost.hazardAt(p)) {
        const glm::vec2 away = p - hazard->center;
        const float length = glm::length(away);
        return length > 1e-4f ? away / length : glm::vec2(1.0f, 0.0f);
    }
    // Nearest passable cell centre, ring by ring.
    constexpr int32_t kReach = 8;
    const glm::ivec2 c = mGrid.cellOf(p);
    for (int32_t ring = 1; ring <= kReach; ++ring) {
        float bestDistance = INFINITY;
        glm::vec2 best(0.0f);
        for (int32_t j = c.y - ring; j <= c.y + ring; ++j)
            for (int32_t i = c.x - ring; i <= c.x + ring; ++i) {
                if (std::max(std::abs(i - c.x), std::abs(j - c.y)) != ring || !mGrid.inGrid(i, j)) continue;
                if (!mCost.passable(mGrid.index(uint32_t(i), uint32_t(j)))) continue;
                const glm::vec2 centre = mGrid.cellCenter(uint32_t(i), uint32_t(j));
                const float d = glm::distance(centre, p);
                if (d < bestDistance) bestDistance = d, best = (centre - p) / std::max(d, 1e-4f);
            }
        if (bestDistance < INFINITY) return best;
    }
    return glm::vec2(0.0f);
}

size_t Navigation::bytes() const {
    const size_t cells = mGrid.cellCount();
    // Terrain cost, the cost field, one potential and flood mark per group.
    return cells * (sizeof(float) + mFields.size() * (sizeof(float) + sizeof(uint8_t))) + mCost.bytes() +
           mGrid.tileCount() * mFields.size() * (sizeof(float) + 1);
}

} // namespace tessera::crowd
