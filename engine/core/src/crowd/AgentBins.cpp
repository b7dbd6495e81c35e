#include "AgentBins.h"

#include "BucketSort.h"
#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cfloat>

#include <glm/common.hpp>
#include <utility>

namespace tessera::crowd {

AgentBins::AgentBins(const NavGrid& grid) : mGrid(grid) {
    uint32_t w = grid.tilesX(), h = grid.tilesZ();
    for (;;) {
        mLevels.emplace_back(size_t(w) * h, scene::Aabb::empty());
        mLevelWidth.push_back(w);
        mLevelHeight.push_back(h);
        if (w == 1 && h == 1) break;
        w = (w + 1) / 2, h = (h + 1) / 2;
    }
    mStart.assign(grid.tileCount() + 1, 0);
}

void AgentBins::build(std::span<const glm::vec3> positions, std::span<const float> radius, float height,
                      uint32_t threads) {
    const uint32_t n = uint32_t(positions.size());
    const uint32_t tiles = mGrid.tileCount();
    mTileOf.resize(n);
    core::parallelForRanges(n, 4096, threads, [&](core::IndexRange r) {
        for (uint32_t a = r.begin; a < r.end; ++a) {
            const glm::ivec2 c = mGrid.cellOf({positions[a].x, positions[a].z});
            const uint32_t i = uint32_t(std::clamp(c.x, 0, int32_t(mGrid.width()) - 1));
            const uint32_t j = uint32_t(std::clamp(c.y, 0, int32_t(mGrid.height()) - 1));
            mTileOf[a] = mGrid.tileOf(i, j);
        }
    });
    bucketSort(mTileOf, tiles, mStart, mAgents, threads);
    mOccupied.clear();
    for (uint32_t t = 0; t < tiles; ++t)
        if (mStart[t + 1] > mStart[t]) mOccupied.push_back(t);

    // Level 0: boxes of the occupied tiles (the others stay empty from the
    // last build or were emptied below).
    std::vector<scene::Aabb>& base = mLevels[0];
    std::fill(base.begin(), base.end(), scene::Aabb::empty());
    core::parallelForRanges(uint32_t(mOccupied.size()), 16, threads, [&](core::IndexRange range) {
        for (uint32_t k = range.begin; k < range.end; ++k) {
            const uint32_t t = mOccupied[k];
            // Corners by min and max inline (what Aabb::expand does, without
            // two calls per agent).
            glm::vec3 lo(FLT_MAX), hi(-FLT_MAX);
            for (uint32_t a : agentsIn(t)) {
                const glm::vec3 p = positions[a];
                lo = glm::min(lo, p - glm::vec3(radius[a], 0.0f, radius[a]));
                hi = glm::max(hi, p + glm::vec3(radius[a], height, radius[a]));
            }
            base[t] = scene::Aabb{lo, hi};
        }
    });
    for (size_t level = 1; level < mLevels.size(); ++level) {
        const uint32_t w = mLevelWidth[level], h = mLevelHeight[level];
        const uint32_t below = mLevelWidth[level - 1], belowH = mLevelHeight[level - 1];
        for (uint32_t z = 0; z < h; ++z)
            for (uint32_t x = 0; x < w; ++x) {
                scene::Aabb box = scene::Aabb::empty();
                for (uint32_t dz = 0; dz < 2; ++dz)
                    for (uint32_t dx = 0; dx < 2; ++dx)
                        if (2 * x + dx < below && 2 * z + dz < belowH)
                            box.expand(mLevels[level - 1][(2 * z + dz) * below + 2 * x + dx]);
                mLevels[level][z * w + x] = box;
            }
    }
}

void AgentBins::cull(const scene::Frustum& frustum, std::vector<uint32_t>& out) const {
    cullNode(frustum, uint32_t(mLevels.size() - 1), 0, 0, false, out);
}

void AgentBins::cullNode(const scene::Frustum& frustum, uint32_t level, uint32_t x, uint32_t z, bool inside,
                         std::vector<uint32_t>& out) const {
    if (x >= mLevelWidth[level] || z >= mLevelHeight[level]) return;
    const scene::Aabb& box = mLevels[level][z * mLevelWidth[level] + x];
    if (box.isEmpty()) return;
    if (!inside) {
        const auto containment = frustum.classify(box);
        if (containment == scene::Frustum::Containment::Outside) return;
        inside = containment == scene::Frustum::Containment::Inside;
    }
    if (level == 0) {
        const auto agents = agentsIn(z * mLevelWidth[0] + x);
        out.insert(out.end(), agents.begin(), agents.end());
        return;
    }
    for (uint32_t dz = 0; dz < 2; ++dz)
        for (uint32_t dx = 0; dx < 2; ++dx) cullNode(frustum, level - 1, 2 * x + dx, 2 * z + dz, inside, out);
}

size_t AgentBins::agentBytes() const { return (mAgents.capacity() + mTileOf.capacity()) * sizeof(uint32_t); }

size_t AgentBins::tileBytes() const {
    size_t boxes = 0;
    for (const auto& level : mLevels) boxes += level.capacity() * sizeof(scene::Aabb);
    return boxes + (mStart.capacity() + mOccupied.capacity()) * sizeof(uint32_t);
}

} // namespace tessera::crowd
