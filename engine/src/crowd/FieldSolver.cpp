#include "FieldSolver.h"

#include "EikonalUpdate.h"
#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::crowd {
namespace {

constexpr float kInf = PotentialField::kUnreachable;
// Sweep rounds (four orders each) per tile solve. One round settles a tile
// whose ghosts are fixed unless its walls bend the paths; the rest carry
// over through the tile staying active.
constexpr int kMaxRounds = 2;

constexpr int32_t kStride = int32_t(NavGrid::kTileCells + 2);
constexpr float kSqrt2 = 1.41421356f;

// The value of the cell at `at` in a window row-major with kStride, from
// its eight neighbours (the multi-stencil scheme: the update on the axes
// and the update on the diagonals, a grid turned by 45 degrees with cells
// sqrt(2) apart; the lower wins). The diagonal stencil removes most of the
// axis-only scheme's error on curved fronts, which grows with distance
// along the diagonals. c holds the costs times spacing of leaving the cell
// in each direction; a diagonal costs the mean of its two axes.
float updateCell(const float* at, const float* c) {
    // Per axis, the neighbour cheapest to reach it by.
    const float left = at[-1] + c[kMinusX], right = at[1] + c[kPlusX];
    const float down = at[-kStride] + c[kMinusZ], up = at[kStride] + c[kPlusZ];
    const bool useLeft = left <= right, useDown = down <= up;
    float u = eikonalUpdate(useLeft ? at[-1] : at[1], useLeft ? c[kMinusX] : c[kPlusX],
                            useDown ? at[-kStride] : at[kStride], useDown ? c[kMinusZ] : c[kPlusZ]);
    // Diagonals, never squeezing between two unreachable cells (a corner
    // of a wall).
    const float minusMinus = kSqrt2 * 0.5f * (c[kMinusX] + c[kMinusZ]);
    const float plusPlus = kSqrt2 * 0.5f * (c[kPlusX] + c[kPlusZ]);
    const float minusPlus = kSqrt2 * 0.5f * (c[kMinusX] + c[kPlusZ]);
    const float plusMinus = kSqrt2 * 0.5f * (c[kPlusX] + c[kMinusZ]);
    const bool openMinusMinus = at[-1] < kInf || at[-kStride] < kInf;
    const bool openPlusPlus = at[1] < kInf || at[kStride] < kInf;
    const bool openMinusPlus = at[-1] < kInf || at[kStride] < kInf;
    const bool openPlusMinus = at[1] < kInf || at[-kStride] < kInf;
    const float mm = openMinusMinus ? at[-kStride - 1] : kInf, pp = openPlusPlus ? at[kStride + 1] : kInf;
    const float mp = openMinusPlus ? at[kStride - 1] : kInf, pm = openPlusMinus ? at[-kStride + 1] : kInf;
    const bool useMM = mm + minusMinus <= pp + plusPlus, useMP = mp + minusPlus <= pm + plusMinus;
    const float diagonal = eikonalUpdate(useMM ? mm : pp, useMM ? minusMinus : plusPlus, useMP ? mp : pm,
                                         useMP ? minusPlus : plusMinus);
    return std::min(u, diagonal);
}

} // namespace

void FieldSolver::solveJob(Job& job, const PotentialField& field, const CostField& cost) const {
    const CellRect r = mGrid.tileCells(job.tile);
    const int32_t w = r.i1 - r.i0 + 1, h = r.j1 - r.j0 + 1;
    const float cell = mGrid.cellSize();
    const std::span<const float> values = field.values();
    // Window (x, y) holds cell (r.i0 + x - 1, r.j0 + y - 1); the ring outside
    // the tile stays fixed during the solve.
    for (int32_t y = 0; y < h + 2; ++y)
        for (int32_t x = 0; x < w + 2; ++x) {
            const int32_t i = r.i0 + x - 1, j = r.j0 + y - 1;
            job.phi[y * kWindow + x] = mGrid.inGrid(i, j) ? values[mGrid.index(uint32_t(i), uint32_t(j))] : kInf;
        }
    // Cost times spacing of leaving each cell in each direction (-x, +x,
    // -z, +z); all four equal where nobody crowds the tile.
    float ch[NavGrid::kTileCells * NavGrid::kTileCells][4];
    float fixed[NavGrid::kTileCells * NavGrid::kTileCells];
    const DirectedCosts* directed = cost.directed(job.tile);
    const std::span<const float> ground = cost.cost();
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) {
            const uint32_t i = uint32_t(r.i0 + x), j = uint32_t(r.j0 + y);
            const float c = ground[mGrid.index(i, j)];
            for (int d = 0; d < 4; ++d)
                ch[y * w + x][d] = (directed ? (*directed)[y * NavGrid::kTileCells + x][d] : c) * cell;
            fixed[y * w + x] = std::isfinite(c) ? field.fixedValue(i, j, c) : -1.0f;
        }
    float before[NavGrid::kTileCells * NavGrid::kTileCells];
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) before[y * w + x] = job.phi[(y + 1) * kWindow + x + 1];

    // Absolute below a cell's worth of potential, relative above: far from
    // the goal a float's last bit is coarser than any absolute tolerance,
    // and sweeping orders may round the fixed point differently.
    const float tolerance = 1e-4f * cell;
    const float relative = 1e-5f;
    job.settled = false;
    for (int round = 0; round < kMaxRounds && !job.settled; ++round) {
        float change = 0.0f;
        for (int order = 0; order < 4; ++order) {
            const bool flipX = order & 1, flipY = order & 2;
            for (int32_t yy = 0; yy < h; ++yy) {
                const int32_t y = flipY ? h - 1 - yy : yy;
                float* row = &job.phi[(y + 1) * kWindow + 1];
                for (int32_t xx = 0; xx < w; ++xx) {
                    const int32_t x = flipX ? w - 1 - xx : xx;
                    const int32_t k = y * w + x;
                    const float* c = ch[k];
                    float u;
                    if (fixed[k] >= 0.0f) u = fixed[k];
                    else if (!(c[0] < kInf)) u = kInf;
                    else {
                        u = updateCell(row + x, c);
                    }
                    // Replacing (not taking the minimum) lets values rise
                    // when costs rose; inf - inf is NaN, hence the test.
                    if (u != row[x])
                        change = std::max(change, std::isfinite(u) && std::isfinite(row[x])
                                                      ? std::abs(u - row[x]) - relative * std::abs(u) : kInf);
                    row[x] = u;
                }
            }
        }
        job.settled = change <= tolerance;
    }

    // What changed along each edge wakes the neighbour across it.
    const float wake = kPropagationTolerance * cell;
    job.lowest = kInf;
    for (int e = 0; e < 4; ++e) job.edgeChanged[e] = false, job.edgeLow[e] = kInf;
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) {
            const float now = job.phi[(y + 1) * kWindow + x + 1], was = before[y * w + x];
            job.lowest = std::min(job.lowest, now);
            const bool changed = std::isfinite(now) && std::isfinite(was) ? std::abs(now - was) > wake : now != was;
            if (!changed) continue;
            const bool edge[4] = {x == 0, x == w - 1, y == 0, y == h - 1};
            for (int e = 0; e < 4; ++e)
                if (edge[e]) job.edgeChanged[e] = true, job.edgeLow[e] = std::min(job.edgeLow[e], now);
        }
}

void FieldSolver::writeBack(Job& job, PotentialField& field) const {
    const CellRect r = mGrid.tileCells(job.tile);
    std::span<float> values = field.mutableValues();
    for (int32_t j = r.j0; j <= r.j1; ++j)
        for (int32_t i = r.i0; i <= r.i1; ++i)
            values[mGrid.index(uint32_t(i), uint32_t(j))] = job.phi[(j - r.j0 + 1) * kWindow + (i - r.i0 + 1)];
}

uint32_t FieldSolver::solve(std::span<PotentialField* const> fields, const CostField& cost,
                            uint32_t tileBudgetPerField, uint32_t threads) {
    std::vector<uint32_t> spent(fields.size(), 0);
    uint32_t total = 0;
    for (;;) {
        mJobs.clear();
        for (uint32_t f = 0; f < fields.size(); ++f) {
            const uint32_t left = tileBudgetPerField - spent[f];
            fields[f]->takeTiles(std::min(kTilesPerPass, left), mTaken);
            spent[f] += uint32_t(mTaken.size());
            for (uint32_t tile : mTaken) {
                Job& job = mJobs.emplace_back();
                job.field = f;
                job.tile = tile;
            }
        }
        if (mJobs.empty()) break;
        total += uint32_t(mJobs.size());
        // Solve every window from the values before the pass, then write all
        // back: no job reads what another writes.
        core::parallelFor(uint32_t(mJobs.size()), threads,
                          [&](uint32_t k) { solveJob(mJobs[k], *fields[mJobs[k].field], cost); });
        core::parallelFor(uint32_t(mJobs.size()), threads,
                          [&](uint32_t k) { writeBack(mJobs[k], *fields[mJobs[k].field]); });
        const uint32_t tx = mGrid.tilesX(), tz = mGrid.tilesZ();
        for (const Job& job : mJobs) {
            PotentialField& field = *fields[job.field];
            const uint32_t x = job.tile % tx, z = job.tile / tx;
            if (!job.settled) field.activate(job.tile, job.lowest);
            if (job.edgeChanged[0] && x > 0) field.activate(job.tile - 1, job.edgeLow[0]);
            if (job.edgeChanged[1] && x + 1 < tx) field.activate(job.tile + 1, job.edgeLow[1]);
            if (job.edgeChanged[2] && z > 0) field.activate(job.tile - tx, job.edgeLow[2]);
            if (job.edgeChanged[3] && z + 1 < tz) field.activate(job.tile + tx, job.edgeLow[3]);
        }
    }
    return total;
}

} // namespace tessera::crowd
