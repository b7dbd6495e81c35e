#pragma once
// Internal: the uniform spatial hash that finds an agent's neighbours.

#include "tessera/crowd/FloorToInt.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tessera::crowd {

/// Agents sorted into square cells of a fixed size, the cells hashed into
/// a power-of-two table (no grid over the whole map, however large).
/// Rebuilt once per step by a counting sort that keeps agents in ascending
/// index order within a bucket, so queries visit neighbours in the same
/// order whatever the thread count.
class SpatialHash {
public:
    /// Sorts `positions` (world XZ from x and z) into cells of `cellSize`
    /// metres; the cells are found on `threads` threads, the counting sort
    /// itself is one pass.
    void build(std::span<const glm::vec3> positions, float cellSize, uint32_t threads);

    /// Calls f(agent, position) for every agent whose cell lies within
    /// `radius` of `p` along both axes (a superset of those within `radius`),
    /// with its XZ position as of build(); each agent once, cells row by row.
    /// The positions are stored in the hash's own order, so a query reads
    /// them from a few contiguous runs instead of all over the agents' arrays.
    template <class F>
    void forEachNear(glm::vec2 p, float radius, F&& f) const {
        const int32_t x0 = floorToInt((p.x - radius) * mInverseCell);
        const int32_t x1 = floorToInt((p.x + radius) * mInverseCell);
        const int32_t z0 = floorToInt((p.y - radius) * mInverseCell);
        const int32_t z1 = floorToInt((p.y + radius) * mInverseCell);
        const uint32_t span = uint32_t(x1 - x0);
        for (int32_t z = z0; z <= z1; ++z) {
            // A row of cells is a run of consecutive buckets, so its agents
            // are one run of slots (two if it wraps around the table).
            const uint32_t first = bucketOf(x0, z), last = first + span;
            const uint32_t row = uint32_t(z) & 0xFFFFu;
            auto visit = [&](uint32_t from, uint32_t to) {
                for (uint32_t s = mStart[from]; s < mStart[to]; ++s) {
                    const uint32_t key = mKey[s];
                    // Other cells hashed into these buckets are skipped by
                    // key, so nobody is visited twice.
                    if ((key >> 16) == row && ((key - uint32_t(x0)) & 0xFFFFu) <= span) f(mAgent[s], mPosition[s]);
                }
            };
            if (last <= mMask) visit(first, last + 1);
            else visit(first, mMask + 1), visit(0, last - mMask);
        }
    }

    /// The cell size of the last build (metres).
    float cellSize() const { return 1.0f / mInverseCell; }
    /// Bytes held (for the memory figures).
    size_t bytes() const;

private:
    // Cell coordinates folded to 16 bits each: cells 65,536 apart share a key
    // and are told apart by the caller's distance test.
    static uint32_t cellKey(int32_t x, int32_t z) { return (uint32_t(x) & 0xFFFFu) | (uint32_t(z) << 16); }
    // Rows hash to random places; cells of a row follow each other.
    uint32_t bucketOf(int32_t x, int32_t z) const {
        return ((uint32_t(z) * 2654435761u >> 8) + uint32_t(x)) & mMask;
    }

    float mInverseCell = 1.0f;
    uint32_t mMask = 1023;
    std::vector<uint32_t> mStart; ///< bucket -> first slot; one extra at the end
    std::vector<uint32_t> mAgent; ///< slot -> agent
    std::vector<uint32_t> mKey;   ///< slot -> cell key
    std::vector<glm::vec2> mPosition; ///< slot -> XZ position
};

} // namespace tessera::crowd
