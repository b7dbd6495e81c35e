#pragma once
// Internal: the incremental, tiled eikonal solver that settles every goal
// group's PotentialField under a budget of tile solves per step.

#include "CostField.h"
#include "tessera/crowd/NavGrid.h"
#include "tessera/crowd/PotentialField.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::crowd {

/// Drives PotentialField's active tiles to convergence: each pass takes up
/// to kTilesPerPass of the lowest-keyed active tiles of every field (the
/// fast iterative method's wavefront, tile-sized), solves each in a private
/// window with the values around it as fixed ghosts (fast sweeping, four
/// orders, until it settles), writes them back and activates the neighbours
/// whose ghost cells changed. Costs may differ by direction of travel
/// (CostField's crowding): the update takes, on each axis, the neighbour
/// with the lowest potential plus cost of getting there, and solves the
/// anisotropic quadratic (Treuille et al. 2006, section 4.3).
///
/// Deterministic for any thread count: a pass's tiles are distinct, they read
/// only values from before the pass (copied into their windows first) and
/// write only their own cells, and the bookkeeping between passes is serial.
class FieldSolver {
public:
    static constexpr uint32_t kTilesPerPass = 64;
    /// A potential change smaller than this fraction of a cell's flat
    /// crossing cost does not wake the neighbours.
    static constexpr float kPropagationTolerance = 0.01f;

    explicit FieldSolver(const NavGrid& grid) : mGrid(grid) {}

    /// Solves until every field is settled or each has spent
    /// `tileBudgetPerField` tile solves (UINT32_MAX: until settled), over
    /// the costs of `cost`. Returns the tile solves done.
    uint32_t solve(std::span<PotentialField* const> fields, const CostField& cost, uint32_t tileBudgetPerField,
                   uint32_t threads);

private:
    static constexpr uint32_t kCells = NavGrid::kTileCells * NavGrid::kTileCells;
    static constexpr uint32_t kWindow = NavGrid::kTileCells + 2;
    /// Jobs swept together, cell by cell: a sweep is a chain of dependent
    /// updates (each cell reads the one before), so on its own it waits on
    /// every update's latency; independent tiles interleaved keep the core
    /// busy instead.
    static constexpr uint32_t kInterleave = 4;

    /// What a cell's update needs besides its neighbours: for each direction
    /// of travel, cost times spacing and its inverse square; the same for the
    /// four diagonals (cells sqrt(2) apart, costing the mean of their axes).
    struct CellCosts {
        float axis[4], axisInverse[4];         // -x, +x, -z, +z
        float diagonal[4], diagonalInverse[4]; // (-x,-z), (+x,+z), (-x,+z), (+x,-z)
    };
    enum CellMode : uint8_t { kSolve, kSolveDirected, kFixed, kWall, kOutside };

    /// One tile of one field in a pass: its window (the tile plus a ring of
    /// ghost cells, row stride kWindow, full size even for a tile the grid's
    /// edge clips), its cells' costs and modes, and what solving it changed.
    struct Job {
        uint32_t field = 0;
        uint32_t tile = 0;
        float phi[kWindow * kWindow];
        float before[kCells];
        float fixed[kCells];
        CellMode mode[kCells];
        CellCosts costs[kCells];
        bool edgeChanged[4] = {}; ///< -X, +X, -Z, +Z
        float edgeLow[4] = {};    ///< lowest new value along each changed edge
        bool settled = true;
        float lowest = 0.0f;
    };

    void prepare(Job& job, const PotentialField& field, const CostField& cost) const;
    void sweep(std::span<Job* const> jobs) const;
    void finish(Job& job) const;
    void writeBack(Job& job, PotentialField& field) const;

    const NavGrid& mGrid;
    std::vector<Job> mJobs;
    std::vector<uint32_t> mTaken;
};

} // namespace tessera::crowd
