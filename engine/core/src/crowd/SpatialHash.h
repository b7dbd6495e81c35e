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

/// A neighbour found by SpatialHash::nearest().
struct NearAgent {
    uint32_t agent = 0;
    float distance2 = 0.0f; ///< squared distance
    glm::vec2 offset{0.0f}; ///< its position less the query point
};

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
        forEachRun(p, radius, [&](uint32_t first, uint32_t end, uint32_t row, uint32_t x0, uint32_t span) {
            for (uint32_t s = first; s < end; ++s)
                if (inRow(mKey[s], row, x0, span)) f(mAgent[s], mPosition[s]);
        });
    }

    /// The up to `count` (at most kMaxNearest) agents nearest `p` within
    /// `radius`, `self` left out, nearest first (equal distances in the
    /// order forEachNear visits them), into `out`; returns how many. Looks
    /// within `closeRadius` first, and over the rest of `radius` only when
    /// that found fewer than `count` (closeRadius >= radius: one look).
    uint32_t nearest(glm::vec2 p, uint32_t self, float closeRadius, float radius, uint32_t count,
                     NearAgent* out) const;
    static constexpr uint32_t kMaxNearest = 16;
    /// The cell size of the last build (metres).
    float cellSize() const { return 1.0f / mInverseCell; }
    /// Bytes held (for the memory figures).
    size_t bytes() const;

private:
    // Calls f(first, end, row, x0, span) for each run of slots holding the
    // cells within `radius` of `p` along both axes: a row of cells is a run
    // of consecutive buckets, so its agents are one run of slots (two where
    // it wraps around the table). Other cells hashed into the same buckets
    // share the run; inRow() tells them apart.
    template <class F>
    void forEachRun(glm::vec2 p, float radius, F&& f) const {
        const int32_t x0 = floorToInt((p.x - radius) * mInverseCell);
        const int32_t x1 = floorToInt((p.x + radius) * mInverseCell);
        const int32_t z0 = floorToInt((p.y - radius) * mInverseCell);
        const int32_t z1 = floorToInt((p.y + radius) * mInverseCell);
        const uint32_t span = uint32_t(x1 - x0);
        for (int32_t z = z0; z <= z1; ++z) {
            const uint32_t first = bucketOf(x0, z), last = first + span;
            const uint32_t row = uint32_t(z) & 0xFFFFu;
            if (last <= mMask) {
                f(mStart[first], mStart[last + 1], row, uint32_t(x0), span);
            } else {
                f(mStart[first], mStart[mMask + 1], row, uint32_t(x0), span);
                f(mStart[0], mStart[last - mMask], row, uint32_t(x0), span);
            }
        }
    }
    // Whether a slot's key is a cell of row `row` from x0 to x0 + span.
    static bool inRow(uint32_t key, uint32_t row, uint32_t x0, uint32_t span) {
        return (key >> 16) == row && ((key - x0) & 0xFFFFu) <= span;
    }
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
