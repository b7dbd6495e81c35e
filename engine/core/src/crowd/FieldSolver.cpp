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
// and the update on the diagonals, a grid turned by 45 degrees; the lower
// wins). The diagonal stencil removes most of the axis-only scheme's error
// on curved fronts, which grows with distance along the diagonals.
//
// Where each axis costs the same both ways, the neighbour cheaper to reach
// on each axis gives the lowest value. Where the crowd makes a direction
// dearer than its opposite (kDirected), every quadrant is tried and the
// lowest taken: choosing per axis by the one-sided values jumps between two
// solutions as the neighbours' values cross, the update is then not
// monotone, and sweeps that replace values can cycle without settling (a
// counterflow's costs kept the first solve of a 2,000-agent crowd going to
// the solver's cap).
template <bool kDirected, class Costs>
float updateCell(const float* at, const Costs& c) {
    const float x[2] = {at[-1], at[1]}, z[2] = {at[-kStride], at[kStride]};
    // Diagonals, never squeezing between two unreachable cells (a corner
    // of a wall): (-x,-z), (+x,+z), (-x,+z), (+x,-z).
    const float d[4] = {at[-1] < kInf || at[-kStride] < kInf ? at[-kStride - 1] : kInf,
                        at[1] < kInf || at[kStride] < kInf ? at[kStride + 1] : kInf,
                        at[-1] < kInf || at[kStride] < kInf ? at[kStride - 1] : kInf,
                        at[1] < kInf || at[-kStride] < kInf ? at[-kStride + 1] : kInf};
    if constexpr (!kDirected) {
        // Per axis, the neighbour cheapest to reach it by.
        const int sx = x[0] + c.axis[kMinusX] <= x[1] + c.axis[kPlusX] ? 0 : 1;
        const int sz = z[0] + c.axis[kMinusZ] <= z[1] + c.axis[kPlusZ] ? 0 : 1;
        const float u = eikonalUpdate(x[sx], c.axis[kMinusX + sx], c.axisInverse[kMinusX + sx], z[sz],
                                      c.axis[kMinusZ + sz], c.axisInverse[kMinusZ + sz]);
        const int one = d[0] + c.diagonal[0] <= d[1] + c.diagonal[1] ? 0 : 1;
        const int two = d[2] + c.diagonal[2] <= d[3] + c.diagonal[3] ? 2 : 3;
        return std::min(u, eikonalUpdate(d[one], c.diagonal[one], c.diagonalInverse[one], d[two], c.diagonal[two],
                                         c.diagonalInverse[two]));
    } else {
        // Both neighbours of an axis only where its two directions differ.
        const bool bothX = c.axis[kMinusX] != c.axis[kPlusX], bothZ = c.axis[kMinusZ] != c.axis[kPlusZ];
        const bool bothOne = c.diagonal[0] != c.diagonal[1], bothTwo = c.diagonal[2] != c.diagonal[3];
        const int sx0 = bothX || x[0] + c.axis[kMinusX] <= x[1] + c.axis[kPlusX] ? 0 : 1, sx1 = bothX ? 1 : sx0;
        const int sz0 = bothZ || z[0] + c.axis[kMinusZ] <= z[1] + c.axis[kPlusZ] ? 0 : 1, sz1 = bothZ ? 1 : sz0;
        const int o0 = bothOne || d[0] + c.diagonal[0] <= d[1] + c.diagonal[1] ? 0 : 1, o1 = bothOne ? 1 : o0;
        const int t0 = bothTwo || d[2] + c.diagonal[2] <= d[3] + c.diagonal[3] ? 2 : 3, t1 = bothTwo ? 3 : t0;
        float u = kInf;
        for (int sx = sx0; sx <= sx1; ++sx)
            for (int sz = sz0; sz <= sz1; ++sz)
                u = std::min(u, eikonalUpdate(x[sx], c.axis[kMinusX + sx], c.axisInverse[kMinusX + sx], z[sz],
                                              c.axis[kMinusZ + sz], c.axisInverse[kMinusZ + sz]));
        for (int one = o0; one <= o1; ++one)
            for (int two = t0; two <= t1; ++two)
                u = std::min(u, eikonalUpdate(d[one], c.diagonal[one], c.diagonalInverse[one], d[two], c.diagonal[two],
                                              c.diagonalInverse[two]));
        return u;
    }
}

// Change between two potentials that counts towards settling: absolute, less
// a relative part (far from the goal a float's last bit is coarser than any
// absolute tolerance); infinity when reachability changed.
float settlingChange(float now, float was) {
    if (now == was) return 0.0f;
    return std::isfinite(now) && std::isfinite(was) ? std::abs(now - was) - 1e-5f * std::abs(now) : kInf;
}

} // namespace

void FieldSolver::prepare(Job& job, const PotentialField& field, const CostField& cost) const {
    const CellRect r = mGrid.tileCells(job.tile);
    const int32_t w = r.i1 - r.i0 + 1, h = r.j1 - r.j0 + 1;
    const float cell = mGrid.cellSize();
    const std::span<const float> values = field.values();
    // Window (x, y) holds cell (r.i0 + x - 1, r.j0 + y - 1); the ring outside
    // the tile stays fixed during the solve.
    for (int32_t y = 0; y < int32_t(kWindow); ++y)
        for (int32_t x = 0; x < int32_t(kWindow); ++x) {
            const int32_t i = r.i0 + x - 1, j = r.j0 + y - 1;
            const bool loaded = x <= w + 1 && y <= h + 1 && mGrid.inGrid(i, j);
            job.phi[y * kWindow + x] = loaded ? values[mGrid.index(uint32_t(i), uint32_t(j))] : kInf;
        }
    const DirectedCosts* directed = cost.directed(job.tile);
    const std::span<const float> ground = cost.cost();
    constexpr int32_t n = int32_t(NavGrid::kTileCells);
    for (int32_t y = 0; y < n; ++y)
        for (int32_t x = 0; x < n; ++x) {
            const int32_t k = y * n + x;
            job.before[k] = job.phi[(y + 1) * kWindow + x + 1];
            if (x >= w || y >= h) {
                job.mode[k] = kOutside;
                continue;
            }
            const uint32_t i = uint32_t(r.i0 + x), j = uint32_t(r.j0 + y);
            const float c = ground[mGrid.index(i, j)];
            if (!std::isfinite(c)) {
                job.mode[k] = kWall;
                continue;
            }
            job.fixed[k] = field.fixedValue(i, j, c);
            CellCosts& costs = job.costs[k];
            float ch[4];
            for (int d = 0; d < 4; ++d) ch[d] = (directed ? (*directed)[k][d] : c) * cell;
            const bool oneWayDearer = ch[kMinusX] != ch[kPlusX] || ch[kMinusZ] != ch[kPlusZ];
            job.mode[k] = job.fixed[k] >= 0.0f ? kFixed : oneWayDearer ? kSolveDirected : kSolve;
            const float diagonal[4] = {ch[kMinusX] + ch[kMinusZ], ch[kPlusX] + ch[kPlusZ], ch[kMinusX] + ch[kPlusZ],
                                       ch[kPlusX] + ch[kMinusZ]};
            for (int d = 0; d < 4; ++d) {
                costs.axis[d] = ch[d];
                costs.axisInverse[d] = 1.0f / (ch[d] * ch[d]);
                costs.diagonal[d] = kSqrt2 * 0.5f * diagonal[d];
                costs.diagonalInverse[d] = 1.0f / (costs.diagonal[d] * costs.diagonal[d]);
            }
        }
    job.settled = false;
}

void FieldSolver::sweep(std::span<Job* const> jobs) const {
    // A round of four sweeps that moved nothing by more than what would wake
    // a neighbour leaves a tile settled: navigation needs no finer answer,
    // and most re-solves after small cost changes end after one round.
    const float tolerance = kPropagationTolerance * mGrid.cellSize();
    constexpr int32_t n = int32_t(NavGrid::kTileCells);
    for (int round = 0; round < kMaxRounds; ++round) {
        float change[kInterleave] = {};
        bool any = false;
        for (Job* job : jobs) any |= !job->settled;
        if (!any) break;
        for (int order = 0; order < 4; ++order) {
            const bool flipX = order & 1, flipY = order & 2;
            for (int32_t yy = 0; yy < n; ++yy) {
                const int32_t y = flipY ? n - 1 - yy : yy;
                for (int32_t xx = 0; xx < n; ++xx) {
                    const int32_t x = flipX ? n - 1 - xx : xx;
                    const int32_t k = y * n + x;
                    // The jobs' updates do not depend on each other.
                    for (size_t q = 0; q < jobs.size(); ++q) {
                        Job& job = *jobs[q];
                        const CellMode mode = job.mode[k];
                        if (job.settled || mode == kOutside) continue;
                        float* at = &job.phi[(y + 1) * kWindow + x + 1];
                        // Replacing (not taking the minimum) lets values
                        // rise when costs rose.
                        const float u = mode == kSolve           ? updateCell<false>(at, job.costs[k])
                                        : mode == kSolveDirected ? updateCell<true>(at, job.costs[k])
                                        : mode == kFixed         ? job.fixed[k]
                                                                 : kInf;
                        change[q] = std::max(change[q], settlingChange(u, *at));
                        *at = u;
                    }
                }
            }
        }
        for (size_t q = 0; q < jobs.size(); ++q) jobs[q]->settled |= change[q] <= tolerance;
    }
}

void FieldSolver::finish(Job& job) const {
    // What changed along each edge wakes the neighbour across it.
    const CellRect r = mGrid.tileCells(job.tile);
    const int32_t w = r.i1 - r.i0 + 1, h = r.j1 - r.j0 + 1;
    const float wake = kPropagationTolerance * mGrid.cellSize();
    job.lowest = kInf;
    for (int e = 0; e < 4; ++e) job.edgeChanged[e] = false, job.edgeLow[e] = kInf;
    for (int32_t y = 0; y < h; ++y)
        for (int32_t x = 0; x < w; ++x) {
            const float now = job.phi[(y + 1) * kWindow + x + 1];
            const float was = job.before[y * int32_t(NavGrid::kTileCells) + x];
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
        core::parallelForRanges(uint32_t(mJobs.size()), kInterleave, threads, [&](core::IndexRange r) {
            Job* group[kInterleave];
            for (uint32_t k = r.begin; k < r.end; ++k) {
                group[k - r.begin] = &mJobs[k];
                prepare(mJobs[k], *fields[mJobs[k].field], cost);
            }
            sweep(std::span<Job* const>(group, r.end - r.begin));
            for (uint32_t k = r.begin; k < r.end; ++k) finish(mJobs[k]);
        });
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
