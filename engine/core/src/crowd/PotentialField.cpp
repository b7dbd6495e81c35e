#include "tessera/crowd/PotentialField.h"

#include "tessera/crowd/FloorToInt.h"

#include <algorithm>
#include <cmath>

namespace tessera::crowd {

PotentialField::PotentialField(const NavGrid& grid, const Region& goal)
    : mGrid(&grid), mGoal(goal), mPhi(grid.cellCount(), kUnreachable), mTileKey(grid.tileCount(), 0.0f),
      mTileActive(grid.tileCount(), 0), mMark(grid.cellCount(), 0) {}

float PotentialField::sample(glm::vec2 p) const {
    const float h = mGrid->cellSize();
    const glm::vec2 f = p / h - 0.5f;
    const int32_t i = floorToInt(f.x), j = floorToInt(f.y);
    const float tx = f.x - float(i), tz = f.y - float(j);
    const float v[4] = {cellValue(i, j), cellValue(i + 1, j), cellValue(i, j + 1), cellValue(i + 1, j + 1)};
    const float w[4] = {(1 - tx) * (1 - tz), tx * (1 - tz), (1 - tx) * tz, tx * tz};
    float sum = 0.0f, weight = 0.0f;
    for (int k = 0; k < 4; ++k)
        if (v[k] < kUnreachable) sum += w[k] * v[k], weight += w[k];
    return weight > 0.0f ? sum / weight : kUnreachable;
}

bool PotentialField::reachable(glm::vec2 p) const {
    const glm::ivec2 c = mGrid->cellOf(p);
    return cellValue(c.x, c.y) < kUnreachable;
}

glm::vec2 PotentialField::descent(glm::vec2 p) const {
    const float h = mGrid->cellSize();
    const glm::vec2 f = p / h - 0.5f;
    const int32_t i = floorToInt(f.x), j = floorToInt(f.y);
    const float tx = f.x - float(i), tz = f.y - float(j);
    float v00, v10, v01, v11;
    // Inside the grid, two reads of two cells each (every walking agent
    // asks, every step); at the edges, cell by cell.
    if (i >= 0 && j >= 0 && uint32_t(i) + 1 < mGrid->width() && uint32_t(j) + 1 < mGrid->height()) {
        const float* row = mPhi.data() + mGrid->index(uint32_t(i), uint32_t(j));
        v00 = row[0], v10 = row[1], v01 = row[mGrid->width()], v11 = row[mGrid->width() + 1];
    } else {
        v00 = cellValue(i, j), v10 = cellValue(i + 1, j), v01 = cellValue(i, j + 1), v11 = cellValue(i + 1, j + 1);
    }
    // All reachable (nearly always): no walls to stand in for.
    if (std::max(std::max(v00, v10), std::max(v01, v11)) < kUnreachable) {
        const glm::vec2 gradient((v10 - v00) * (1 - tz) + (v11 - v01) * tz, (v01 - v00) * (1 - tx) + (v11 - v10) * tx);
        const float length = glm::length(gradient);
        return length > 1e-6f * h ? -gradient / length : glm::vec2(0.0f);
    }
    float highest = -1.0f;
    for (float v : {v00, v10, v01, v11})
        if (v < kUnreachable) highest = std::max(highest, v);
    if (highest < 0.0f) return glm::vec2(0.0f);
    // Walls and unreachable cells read as a step up of two cells of flat
    // ground above the highest reachable corner, so the slope leads away.
    const float wall = highest + 2.0f * h;
    for (float* v : {&v00, &v10, &v01, &v11})
        if (!(*v < kUnreachable)) *v = wall;
    const glm::vec2 gradient((v10 - v00) * (1 - tz) + (v11 - v01) * tz, (v01 - v00) * (1 - tx) + (v11 - v10) * tx);
    const float length = glm::length(gradient);
    return length > 1e-6f * h ? -gradient / length : glm::vec2(0.0f);
}

void PotentialField::activate(uint32_t tile, float key) {
    if (!mTileActive[tile]) {
        mTileActive[tile] = 1;
        mTileKey[tile] = key;
        mActive.push_back(tile);
    } else {
        mTileKey[tile] = std::min(mTileKey[tile], key);
    }
}

void PotentialField::activateByContent(uint32_t tile) {
    const CellRect r = mGrid->tileCells(tile);
    float lowest = kUnreachable;
    // The ring around the tile too: a tile reset to unreachable is reached
    // from its neighbours.
    for (int32_t j = r.j0 - 1; j <= r.j1 + 1; ++j)
        for (int32_t i = r.i0 - 1; i <= r.i1 + 1; ++i) lowest = std::min(lowest, cellValue(i, j));
    activate(tile, lowest);
}

void PotentialField::activateGoalTiles() {
    const CellRect cells = mGrid->cellsTouching(mGoal.boundsMin(), mGoal.boundsMax());
    if (cells.empty()) return;
    constexpr int32_t n = int32_t(NavGrid::kTileCells);
    for (int32_t tj = cells.j0 / n; tj <= cells.j1 / n; ++tj)
        for (int32_t ti = cells.i0 / n; ti <= cells.i1 / n; ++ti)
            activate(uint32_t(tj) * mGrid->tilesX() + uint32_t(ti), 0.0f);
}

void PotentialField::invalidateDependents(std::span<const uint32_t> cells,
                                          const std::function<float(uint32_t)>& highestCost) {
    if (cells.empty()) return;
    const float h = mGrid->cellSize();
    const uint32_t width = mGrid->width();
    std::vector<uint32_t> reset;
    int32_t i0 = INT32_MAX, j0 = INT32_MAX, i1 = INT32_MIN, j1 = INT32_MIN;
    for (uint32_t c : cells) {
        if (!mMark[c]) mMark[c] = 1, reset.push_back(c);
        const int32_t i = int32_t(c % width), j = int32_t(c / width);
        i0 = std::min(i0, i), j0 = std::min(j0, j), i1 = std::max(i1, i), j1 = std::max(j1, j);
    }
    // The reset stays within a margin as wide as the changed area (at least
    // a tile): enough to hold any pocket the change can enclose, which would
    // otherwise count up to infinity. The discrete dependency cone fans out
    // at 45 degrees and would reach a quarter of the map; beyond the margin
    // the stale values rise to the detour's length as the tiles re-solve.
    const int32_t margin = std::max(int32_t(NavGrid::kTileCells), std::max(i1 - i0, j1 - j0));
    i0 -= margin, j0 -= margin, i1 += margin, j1 += margin;
    // Flood downstream: neighbour n depends on cell c when c is the lower of
    // n's two neighbours on that axis and the upwind update of n used that
    // axis (the same test as the update itself, on the values before reset).
    for (size_t k = 0; k < reset.size(); ++k) {
        const uint32_t c = reset[k];
        const float value = mPhi[c];
        if (!(value < kUnreachable)) continue;
        const int32_t ci = int32_t(c % width), cj = int32_t(c / width);
        const int32_t di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
        for (int e = 0; e < 4; ++e) {
            const int32_t ni = ci + di[e], nj = cj + dj[e];
            if (!mGrid->inGrid(ni, nj) || ni < i0 || ni > i1 || nj < j0 || nj > j1) continue;
            const uint32_t n = mGrid->index(uint32_t(ni), uint32_t(nj));
            if (mMark[n] || !(mPhi[n] < kUnreachable) || mPhi[n] <= value) continue;
            // Along c's axis, n's other neighbour on the far side of n.
            const float across = cellValue(ni + di[e], nj + dj[e]);
            if (across < value) continue; // n's update took the other side of this axis
            const bool horizontal = dj[e] == 0;
            const float other = horizontal ? std::min(cellValue(ni, nj - 1), cellValue(ni, nj + 1))
                                           : std::min(cellValue(ni - 1, nj), cellValue(ni + 1, nj));
            // One-sided update from the other axis alone: c was not used.
            if (other + highestCost(n) * h <= value) continue;
            mMark[n] = 1;
            reset.push_back(n);
        }
    }
    std::vector<uint32_t> tiles;
    for (uint32_t c : reset) {
        mPhi[c] = kUnreachable;
        mMark[c] = 0;
        tiles.push_back(mGrid->tileOf(c % width, c / width));
    }
    std::sort(tiles.begin(), tiles.end());
    tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
    // Each reset tile is re-solved from its ring; its neighbours also get a
    // look, since a reset cell on a tile edge is their ghost.
    const uint32_t tx = mGrid->tilesX(), tz = mGrid->tilesZ();
    for (uint32_t t : tiles) {
        const uint32_t x = t % tx, z = t / tx;
        activateByContent(t);
        if (x > 0) activateByContent(t - 1);
        if (x + 1 < tx) activateByContent(t + 1);
        if (z > 0) activateByContent(t - tx);
        if (z + 1 < tz) activateByContent(t + tx);
    }
}

void PotentialField::takeTiles(uint32_t count, std::vector<uint32_t>& out) {
    out.clear();
    if (mActive.empty() || count == 0) return;
    auto before = [this](uint32_t a, uint32_t b) {
        return mTileKey[a] < mTileKey[b] || (mTileKey[a] == mTileKey[b] && a < b);
    };
    if (count < mActive.size()) {
        std::nth_element(mActive.begin(), mActive.begin() + count, mActive.end(), before);
        out.assign(mActive.begin(), mActive.begin() + count);
        mActive.erase(mActive.begin(), mActive.begin() + count);
    } else {
        out.swap(mActive);
        mActive.clear();
    }
    std::sort(out.begin(), out.end(), before);
    for (uint32_t t : out) mTileActive[t] = 0;
}

} // namespace tessera::crowd
