#include "CostField.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::crowd {
namespace {

// A ground cost that rose by more than this factor resets the values
// derived through the cell instead of letting them creep up pass by pass.
constexpr float kSharpRise = 1.5f;
constexpr int32_t kTile = int32_t(NavGrid::kTileCells);
// Extra cost (times the ground's) of walking with a dense oncoming stream
// on one's right.
constexpr float kLanePenalty = 2.0f;

bool discTouchesCell(glm::vec2 center, float radius, glm::vec2 lo, glm::vec2 hi) {
    const glm::vec2 nearest = glm::clamp(center, lo, hi);
    const glm::vec2 d = center - nearest;
    return glm::dot(d, d) <= radius * radius;
}

} // namespace

CostField::CostField(const NavGrid& grid, const CrowdSettings& settings)
    : mGrid(grid), mDensityMin(settings.densityMin),
      mDensityRange(std::max(settings.densityMax - settings.densityMin, 1e-3f)),
      mSlowest(1.0f / (1.0f + settings.densityCostWeight)), mFlowSpeed(settings.flowSpeed), mCost(grid.cellCount()),
      mSamples(grid.tileCount()), mDirected(grid.tileCount()) {
    for (uint32_t c = 0; c < grid.cellCount(); ++c) mCost[c] = grid.terrainCost(c);
}

CostField::~CostField() = default;

bool CostField::passableAt(glm::vec2 p) const {
    const glm::ivec2 c = mGrid.cellOf(p);
    return mGrid.inGrid(c.x, c.y) && passable(mGrid.index(uint32_t(c.x), uint32_t(c.y)));
}

float CostField::highestCost(uint32_t cell) const {
    const uint32_t i = cell % mGrid.width(), j = cell / mGrid.width();
    const DirectedCosts* directed = mDirected[mGrid.tileOf(i, j)].get();
    if (!directed) return mCost[cell];
    const auto& c = (*directed)[(j % kTile) * kTile + i % kTile];
    return std::max(std::max(c[0], c[1]), std::max(c[2], c[3]));
}

void CostField::expireHazards(double now, std::vector<CellRect>& freed) {
    auto expired = [now](const Hazard& h) { return h.expires <= now; };
    for (const Hazard& h : mHazards)
        if (expired(h)) freed.push_back(hazardCells(h));
    std::erase_if(mHazards, expired);
}

const Hazard* CostField::hazardAt(glm::vec2 p) const {
    for (const Hazard& h : mHazards)
        if (glm::distance(p, h.center) <= h.radius) return &h;
    return nullptr;
}

CellRect CostField::hazardCells(const Hazard& hazard) const {
    return mGrid.cellsTouching(hazard.center - hazard.radius, hazard.center + hazard.radius);
}

void CostField::recountTile(uint32_t tile, std::span<const uint32_t> agents, std::span<const glm::vec3> positions,
                            std::span<const glm::vec2> velocities) {
    if (agents.empty()) {
        mSamples[tile].reset();
        return;
    }
    if (!mSamples[tile]) mSamples[tile] = std::make_unique<Samples>();
    Samples& samples = *mSamples[tile];
    samples = Samples{};
    const CellRect r = mGrid.tileCells(tile);
    for (uint32_t a : agents) {
        const glm::ivec2 c = mGrid.cellOf({positions[a].x, positions[a].z});
        const int32_t k = (std::clamp(c.y, r.j0, r.j1) - r.j0) * kTile + std::clamp(c.x, r.i0, r.i1) - r.i0;
        if (samples.count[k] < UINT16_MAX) ++samples.count[k], samples.velocity[k] += velocities[a];
    }
}

void CostField::crowdAt(glm::vec2 p, float& count, glm::vec2& velocity) const {
    count = 0.0f;
    velocity = glm::vec2(0.0f);
    const glm::ivec2 c = mGrid.cellOf(p);
    if (!mGrid.inGrid(c.x, c.y)) return;
    const Samples* samples = mSamples[mGrid.tileOf(uint32_t(c.x), uint32_t(c.y))].get();
    if (!samples) return;
    const int32_t k = (c.y % kTile) * kTile + c.x % kTile;
    count = float(samples->count[k]);
    velocity = samples->velocity[k];
}

void CostField::crowdAround(int32_t i, int32_t j, float& count, glm::vec2& velocity) const {
    count = 0.0f;
    velocity = glm::vec2(0.0f);
    for (int32_t nj = j - 1; nj <= j + 1; ++nj)
        for (int32_t ni = i - 1; ni <= i + 1; ++ni) {
            if (!mGrid.inGrid(ni, nj)) continue;
            const Samples* samples = mSamples[mGrid.tileOf(uint32_t(ni), uint32_t(nj))].get();
            if (!samples) continue;
            const int32_t k = (nj % kTile) * kTile + ni % kTile;
            count += float(samples->count[k]);
            velocity += samples->velocity[k];
        }
}

float CostField::densityFraction(float count) const {
    return std::clamp((count / (9.0f * mGrid.cellSize() * mGrid.cellSize()) - mDensityMin) / mDensityRange, 0.0f, 1.0f);
}

// The crowd around one tile: box-filtered agent counts and summed
// velocities of its cells and of the cells around it that the look-ahead
// reaches, gathered once per tile rather than per cell and direction.
struct CostField::CrowdWindow {
    static constexpr int32_t kMargin = 2, kSize = kTile + 2 * kMargin;
    int32_t i0 = 0, j0 = 0; ///< the cell at window (0, 0)
    float count[kSize * kSize];
    glm::vec2 velocity[kSize * kSize];

    int32_t at(int32_t i, int32_t j) const { return (j - j0) * kSize + (i - i0); }
};

void CostField::gatherCrowd(uint32_t tile, CrowdWindow& window) const {
    const CellRect r = mGrid.tileCells(tile);
    window.i0 = r.i0 - CrowdWindow::kMargin;
    window.j0 = r.j0 - CrowdWindow::kMargin;
    for (int32_t y = 0; y < CrowdWindow::kSize; ++y)
        for (int32_t x = 0; x < CrowdWindow::kSize; ++x)
            crowdAround(window.i0 + x, window.j0 + y, window.count[y * CrowdWindow::kSize + x],
                        window.velocity[y * CrowdWindow::kSize + x]);
}

float CostField::crowdingCost(const CrowdWindow& window, int32_t i, int32_t j, int d) const {
    const int32_t di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
    // Right of the direction of travel (clockwise seen from above).
    const int32_t ri[4] = {0, 0, 1, -1}, rj[4] = {-1, 1, 0, 0};
    float extra = 0.0f;
    // Ahead: the speed the crowd lets one walk there blends from a free walk
    // to the crowd's own velocity along the way (1 with the stream,
    // mSlowest against it or into a standing crowd).
    const int32_t ahead = window.at(i + di[d], j + dj[d]);
    if (const float t = densityFraction(window.count[ahead]); t > 0.0f) {
        const glm::vec2 v = window.velocity[ahead];
        const float along = (v.x * float(di[d]) + v.y * float(dj[d])) / (window.count[ahead] * mFlowSpeed);
        extra += 1.0f / (1.0f + t * (std::clamp(along, mSlowest, 1.0f) - 1.0f)) - 1.0f;
    }
    // Ahead and to the right: oncoming walkers there mean passing them on
    // the wrong side. Keeping them on the left makes opposing groups choose
    // opposite sides long before they meet: lanes instead of a jam.
    const int32_t right = window.at(i + di[d] + ri[d], j + dj[d] + rj[d]);
    if (const float t = densityFraction(window.count[right]); t > 0.0f) {
        const glm::vec2 v = window.velocity[right];
        const float against = -(v.x * float(di[d]) + v.y * float(dj[d])) / (window.count[right] * mFlowSpeed);
        extra += kLanePenalty * t * std::clamp(against, 0.0f, 1.0f);
    }
    return extra;
}

bool CostField::recomputeTile(uint32_t tile, std::vector<uint32_t>& raised) {
    const CellRect r = mGrid.tileCells(tile);
    const float h = mGrid.cellSize();
    const glm::vec2 lo = glm::vec2(float(r.i0), float(r.j0)) * h, hi = glm::vec2(float(r.i1 + 1), float(r.j1 + 1)) * h;
    std::vector<const Hazard*> hazards; // only those reaching this tile
    for (const Hazard& hazard : mHazards)
        if (discTouchesCell(hazard.center, hazard.radius, lo, hi)) hazards.push_back(&hazard);
    // Crowding reaches one cell beyond the agents' tiles (the box filter and
    // the look-ahead).
    bool crowdNear = false;
    for (int32_t tj = r.j0 / kTile - 1; tj <= r.j0 / kTile + 1 && !crowdNear; ++tj)
        for (int32_t ti = r.i0 / kTile - 1; ti <= r.i0 / kTile + 1; ++ti)
            if (ti >= 0 && tj >= 0 && uint32_t(ti) < mGrid.tilesX() && uint32_t(tj) < mGrid.tilesZ() &&
                mSamples[uint32_t(tj) * mGrid.tilesX() + uint32_t(ti)]) {
                crowdNear = true;
                break;
            }
    std::unique_ptr<CrowdWindow> window;
    if (crowdNear) {
        window = std::make_unique<CrowdWindow>();
        gatherCrowd(tile, *window);
    }
    DirectedCosts directed;
    bool changed = false, crowded = false;
    for (int32_t j = r.j0; j <= r.j1; ++j)
        for (int32_t i = r.i0; i <= r.i1; ++i) {
            const uint32_t c = mGrid.index(uint32_t(i), uint32_t(j));
            float ground = mGrid.terrainCost(c);
            const glm::vec2 cellLo = glm::vec2(float(i), float(j)) * h;
            for (const Hazard* hazard : hazards)
                if (discTouchesCell(hazard->center, hazard->radius, cellLo, cellLo + h)) ground = NavGrid::kImpassable;
            const float was = mCost[c];
            if (ground != was) {
                changed = true;
                if (ground > was * kSharpRise) raised.push_back(c);
                mCost[c] = ground;
            }
            auto& costs = directed[(j - r.j0) * kTile + (i - r.i0)];
            for (int d = 0; d < 4; ++d) {
                costs[d] = ground;
                if (!window || !(ground < NavGrid::kImpassable)) continue;
                const float extra = crowdingCost(*window, i, j, d);
                if (extra <= 0.0f) continue;
                costs[d] = std::round(8.0f * ground * (1.0f + extra)) * 0.125f;
                crowded |= costs[d] != ground;
            }
        }
    std::unique_ptr<DirectedCosts>& stored = mDirected[tile];
    if (crowded) {
        if (!stored || *stored != directed) changed = true, stored = std::make_unique<DirectedCosts>(directed);
    } else if (stored) {
        changed = true;
        stored.reset();
    }
    return changed;
}

void CostField::recomputeTiles(std::span<const uint32_t> tiles, CostChanges& changes, uint32_t threads) {
    struct TileResult {
        std::vector<uint32_t> raised;
        bool changed = false;
    };
    std::vector<TileResult> results(tiles.size());
    // Each tile writes only its own cells and directed block, and reads the
    // samples, which only recountTile writes.
    core::parallelFor(uint32_t(tiles.size()), threads,
                      [&](uint32_t k) { results[k].changed = recomputeTile(tiles[k], results[k].raised); });
    for (size_t k = 0; k < tiles.size(); ++k) {
        if (!results[k].changed) continue;
        changes.tiles.push_back(tiles[k]);
        changes.raised.insert(changes.raised.end(), results[k].raised.begin(), results[k].raised.end());
    }
}

std::vector<uint32_t> CostField::tilesOf(const CellRect& cells) const {
    std::vector<uint32_t> tiles;
    if (cells.empty()) return tiles;
    for (int32_t tj = cells.j0 / kTile; tj <= cells.j1 / kTile; ++tj)
        for (int32_t ti = cells.i0 / kTile; ti <= cells.i1 / kTile; ++ti)
            tiles.push_back(uint32_t(tj) * mGrid.tilesX() + uint32_t(ti));
    return tiles;
}

size_t CostField::bytes() const {
    size_t blocks = 0;
    for (const auto& s : mSamples) blocks += s ? sizeof(Samples) : 0;
    for (const auto& d : mDirected) blocks += d ? sizeof(DirectedCosts) : 0;
    return mCost.size() * sizeof(float) + (mSamples.size() + mDirected.size()) * sizeof(void*) + blocks;
}

} // namespace tessera::crowd
