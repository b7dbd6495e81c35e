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
// Extra cost (times the ground's) of walking with a dense oncoming crowd
// on one's right.
constexpr float kLanePenalty = 2.0f;
// Extra cost (times the ground's) of walking into a dense crowd that wants
// to go the other way.
constexpr float kCounterPenalty = 4.0f;
// The keep-right look: metres ahead and to the side of the way ahead, and
// the density of oncoming walkers there (agents per square metre) from which
// it costs and at which it costs the most. The side reach spans a passage:
// in one narrower than this, the way along its left side sees every oncoming
// walker on its right, the way along its right side only its wall, so each
// direction's cheapest way is its own right side. From 0.3 agents per square
// metre, not less: a sparse crowd needs no lanes, and costs changing all
// over it kept the solver at its budget.
constexpr float kLaneAheadMetres = 8.0f, kLaneSideMetres = 16.0f, kLaneFrom = 0.3f, kLaneDensity = 0.6f;
// Metres ahead an agent's intended direction is counted in.
constexpr float kAnticipationMetres = 6.0f;

bool discTouchesCell(glm::vec2 center, float radius, glm::vec2 lo, glm::vec2 hi) {
    const glm::vec2 nearest = glm::clamp(center, lo, hi);
    const glm::vec2 d = center - nearest;
    return glm::dot(d, d) <= radius * radius;
}

} // namespace

CostField::CostField(const NavGrid& grid, const CrowdSettings& settings)
    : mGrid(grid), mDensityMin(settings.densityMin),
      mDensityRange(std::max(settings.densityMax - settings.densityMin, 1e-3f)),
      mSlowest(1.0f / (1.0f + settings.densityCostWeight)), mFlowSpeed(settings.flowSpeed),
      mLaneAhead(std::clamp(int32_t(std::lround(kLaneAheadMetres / grid.cellSize())), 1, kTile - 1)),
      mLaneSide(std::clamp(int32_t(std::lround(kLaneSideMetres / grid.cellSize())), 1, kTile - 1)),
      mAnticipation(std::clamp(int32_t(std::lround(kAnticipationMetres / grid.cellSize())), 1, kTile - 1)),
      mCost(grid.cellCount()),
      mSamples(grid.tileCount()), mDirected(grid.tileCount()) {
    for (uint32_t c = 0; c < grid.cellCount(); ++c) mCost[c] = grid.terrainCost(c);
}

CostField::~CostField() = default;

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

void CostField::recountTile(uint32_t tile, const AgentBins& bins, std::span<const glm::vec3> positions,
                            std::span<const glm::vec2> velocities, std::span<const glm::vec2> intentions) {
    const CellRect r = mGrid.tileCells(tile);
    std::unique_ptr<Samples> samples;
    auto deposit = [&](glm::ivec2 c, glm::vec2 u) -> Samples::Cell& {
        if (!samples) samples = std::make_unique<Samples>();
        Samples::Cell& cell = samples->cells[size_t((c.y - r.j0) * kTile + c.x - r.i0)];
        cell.intent[kMinusX] += std::max(-u.x, 0.0f), cell.intent[kPlusX] += std::max(u.x, 0.0f);
        cell.intent[kMinusZ] += std::max(-u.y, 0.0f), cell.intent[kPlusZ] += std::max(u.y, 0.0f);
        return cell;
    };
    // An agent's wish counts once where it stands and once more spread over
    // the way ahead, so a crowd's wishes stay in proportion to its density.
    const float ahead = 1.0f / float(mAnticipation);
    for (uint32_t a : bins.agentsIn(tile)) {
        glm::ivec2 c = mGrid.cellOf({positions[a].x, positions[a].z});
        c = glm::clamp(c, glm::ivec2(r.i0, r.j0), glm::ivec2(r.i1, r.j1));
        Samples::Cell& cell = deposit(c, intentions[a]);
        if (cell.count == UINT16_MAX) continue;
        ++cell.count;
        cell.velocity += velocities[a];
    }
    // Anticipation: where agents of this tile and the tiles around are
    // about to walk counts as wanted that way too (the "predictive
    // discomfort" of continuum crowds). Others then keep out of the way a
    // group is about to take, even while it stands in a queue: the exit of a
    // passage stays clear for those coming through it.
    const float h = mGrid.cellSize();
    const glm::vec2 lo = glm::vec2(float(r.i0), float(r.j0)) * h, hi = glm::vec2(float(r.i1 + 1), float(r.j1 + 1)) * h;
    const float reach = float(mAnticipation) * h;
    const int32_t tx = int32_t(tile % mGrid.tilesX()), tz = int32_t(tile / mGrid.tilesX());
    for (int32_t nz = tz - 1; nz <= tz + 1; ++nz)
        for (int32_t nx = tx - 1; nx <= tx + 1; ++nx) {
            if (nx < 0 || nz < 0 || uint32_t(nx) >= mGrid.tilesX() || uint32_t(nz) >= mGrid.tilesZ()) continue;
            for (uint32_t a : bins.agentsIn(uint32_t(nz) * mGrid.tilesX() + uint32_t(nx))) {
                const glm::vec2 u = intentions[a];
                if (u == glm::vec2(0.0f)) continue;
                const glm::vec2 p(positions[a].x, positions[a].z);
                const glm::vec2 gap = glm::max(glm::max(lo - p, p - hi), glm::vec2(0.0f));
                if (glm::dot(gap, gap) > reach * reach) continue;
                for (int32_t k = 1; k <= mAnticipation; ++k) {
                    const glm::ivec2 c = mGrid.cellOf(p + u * (float(k) * h));
                    if (c.x >= r.i0 && c.x <= r.i1 && c.y >= r.j0 && c.y <= r.j1) deposit(c, u * ahead);
                }
            }
        }
    mSamples[tile] = std::move(samples);
}

void CostField::crowdAt(glm::vec2 p, float& count, glm::vec2& velocity) const {
    count = 0.0f;
    velocity = glm::vec2(0.0f);
    const glm::ivec2 c = mGrid.cellOf(p);
    if (!mGrid.inGrid(c.x, c.y)) return;
    const Samples* samples = mSamples[mGrid.tileOf(uint32_t(c.x), uint32_t(c.y))].get();
    if (!samples) return;
    const Samples::Cell& cell = samples->cells[size_t((c.y % kTile) * kTile + c.x % kTile)];
    count = float(cell.count);
    velocity = cell.velocity;
}

float CostField::densityFraction(float count) const {
    return std::clamp((count / (9.0f * mGrid.cellSize() * mGrid.cellSize()) - mDensityMin) / mDensityRange, 0.0f, 1.0f);
}

// The crowd around one tile, as summed-area tables of the per-cell samples
// over the tile and a margin around it wide enough for every look-ahead:
// any rectangle's sum (the 3 x 3 box filter, the lane look-ahead) is then
// four reads, gathered once per tile rather than per cell and direction.
struct CostField::CrowdWindow {
    int32_t margin = 2, size = kTile + 4;
    int32_t i0 = 0, j0 = 0; ///< the cell at window (0, 0)
    std::vector<float> count;                ///< (size + 1)^2, exclusive prefix sums
    std::vector<glm::vec2> velocity;
    std::vector<std::array<float, 4>> intent;

    template <class T>
    static T sum(const std::vector<T>& table, int32_t stride, int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
        return table[size_t(y1 + 1) * size_t(stride) + size_t(x1 + 1)] - table[size_t(y0) * size_t(stride) + size_t(x1 + 1)] -
               table[size_t(y1 + 1) * size_t(stride) + size_t(x0)] + table[size_t(y0) * size_t(stride) + size_t(x0)];
    }
    /// Sums over cells [ci0, ci1] x [cj0, cj1] (grid coordinates, inside the window).
    float countIn(int32_t ci0, int32_t cj0, int32_t ci1, int32_t cj1) const {
        return sum(count, size + 1, ci0 - i0, cj0 - j0, ci1 - i0, cj1 - j0);
    }
    glm::vec2 velocityIn(int32_t ci0, int32_t cj0, int32_t ci1, int32_t cj1) const {
        return sum(velocity, size + 1, ci0 - i0, cj0 - j0, ci1 - i0, cj1 - j0);
    }
    float intentIn(int d, int32_t ci0, int32_t cj0, int32_t ci1, int32_t cj1) const {
        const int32_t stride = size + 1, x0 = ci0 - i0, y0 = cj0 - j0, x1 = ci1 - i0, y1 = cj1 - j0;
        return intent[size_t(y1 + 1) * size_t(stride) + size_t(x1 + 1)][d] - intent[size_t(y0) * size_t(stride) + size_t(x1 + 1)][d] -
               intent[size_t(y1 + 1) * size_t(stride) + size_t(x0)][d] + intent[size_t(y0) * size_t(stride) + size_t(x0)][d];
    }
};

void CostField::gatherCrowd(uint32_t tile, CrowdWindow& window) const {
    const CellRect r = mGrid.tileCells(tile);
    window.margin = std::max(mLaneAhead, mLaneSide) + 1;
    window.size = kTile + 2 * window.margin;
    window.i0 = r.i0 - window.margin;
    window.j0 = r.j0 - window.margin;
    const int32_t stride = window.size + 1;
    const size_t cells = size_t(stride) * size_t(stride);
    window.count.assign(cells, 0.0f);
    window.velocity.assign(cells, glm::vec2(0.0f));
    window.intent.assign(cells, std::array<float, 4>{});
    for (int32_t y = 0; y < window.size; ++y) {
        float rowCount = 0.0f;
        glm::vec2 rowVelocity(0.0f);
        std::array<float, 4> rowIntent{};
        for (int32_t x = 0; x < window.size; ++x) {
            const int32_t i = window.i0 + x, j = window.j0 + y;
            if (mGrid.inGrid(i, j))
                if (const Samples* samples = mSamples[mGrid.tileOf(uint32_t(i), uint32_t(j))].get()) {
                    const Samples::Cell& cell = samples->cells[size_t((j % kTile) * kTile + i % kTile)];
                    rowCount += float(cell.count);
                    rowVelocity += cell.velocity;
                    for (int d = 0; d < 4; ++d) rowIntent[d] += cell.intent[d];
                }
            const size_t at = size_t(y + 1) * size_t(stride) + size_t(x + 1), above = at - size_t(stride);
            window.count[at] = window.count[above] + rowCount;
            window.velocity[at] = window.velocity[above] + rowVelocity;
            for (int d = 0; d < 4; ++d) window.intent[at][d] = window.intent[above][d] + rowIntent[d];
        }
    }
}

float CostField::crowdingCost(const CrowdWindow& window, int32_t i, int32_t j, int d) const {
    const int32_t di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
    // Right of the direction of travel (clockwise seen from above).
    const int32_t ri[4] = {0, 0, 1, -1}, rj[4] = {-1, 1, 0, 0};
    constexpr int kOpposite[4] = {kPlusX, kMinusX, kPlusZ, kMinusZ};
    float extra = 0.0f;
    // Ahead (3 x 3 cells around the next cell): the speed the crowd lets one
    // walk there blends from a free walk to the crowd's own velocity along
    // the way (1 with the stream, mSlowest against it or into a standing
    // crowd).
    const int32_t ai = i + di[d], aj = j + dj[d];
    const float count = window.countIn(ai - 1, aj - 1, ai + 1, aj + 1);
    if (const float t = densityFraction(count); t > 0.0f) {
        const glm::vec2 v = window.velocityIn(ai - 1, aj - 1, ai + 1, aj + 1);
        const float along = (v.x * float(di[d]) + v.y * float(dj[d])) / (count * mFlowSpeed);
        extra += 1.0f / (1.0f + t * (std::clamp(along, mSlowest, 1.0f) - 1.0f)) - 1.0f;
    }
    // Against those who want to go the other way, whether they move or not:
    // in a jam nobody moves and the velocities say nothing, but each agent
    // still wants to go somewhere. Each group's field then runs through the
    // cells its own side holds.
    extra += kCounterPenalty * densityFraction(window.intentIn(kOpposite[d], ai - 1, aj - 1, ai + 1, aj + 1));
    // Keep right: oncoming walkers ahead and to the right (a strip
    // mLaneAhead cells long and mLaneSide wide beside the way ahead) mean
    // passing them on the wrong side. Looking well ahead, opposing groups
    // choose opposite sides before they meet, and in a passage each takes
    // the side on its right: lanes instead of a jam.
    const int32_t x0 = i + std::min(di[d], di[d] * mLaneAhead) + std::min(ri[d], ri[d] * mLaneSide);
    const int32_t x1 = i + std::max(di[d], di[d] * mLaneAhead) + std::max(ri[d], ri[d] * mLaneSide);
    const int32_t y0 = j + std::min(dj[d], dj[d] * mLaneAhead) + std::min(rj[d], rj[d] * mLaneSide);
    const int32_t y1 = j + std::max(dj[d], dj[d] * mLaneAhead) + std::max(rj[d], rj[d] * mLaneSide);
    const float h = mGrid.cellSize();
    const float onRight = window.intentIn(kOpposite[d], x0, y0, x1, y1) / (float(mLaneAhead * mLaneSide) * h * h);
    extra += kLanePenalty * std::clamp((onRight - kLaneFrom) / (kLaneDensity - kLaneFrom), 0.0f, 1.0f);
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
