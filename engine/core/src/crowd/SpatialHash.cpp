#include "SpatialHash.h"

#include "BucketSort.h"
#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <bit>

#include <glm/vec2.hpp>

namespace tessera::crowd {

void SpatialHash::build(std::span<const glm::vec3> positions, float cellSize, uint32_t threads) {
    const uint32_t n = uint32_t(positions.size());
    mInverseCell = 1.0f / cellSize;
    // About one bucket per agent (at least 1,024) keeps chains short.
    const uint32_t buckets = std::bit_ceil(std::max(n, 1024u));
    mMask = buckets - 1;
    auto cellOf = [&](uint32_t a) {
        return glm::ivec2(floorToInt(positions[a].x * mInverseCell), floorToInt(positions[a].z * mInverseCell));
    };
    // mKey holds each agent's bucket until the slots take their keys.
    std::vector<uint32_t>& bucketOfAgent = mKey;
    bucketOfAgent.resize(n);
    core::parallelForRanges(n, 4096, threads, [&](core::IndexRange r) {
        for (uint32_t a = r.begin; a < r.end; ++a) {
            const glm::ivec2 c = cellOf(a);
            bucketOfAgent[a] = bucketOf(c.x, c.y);
        }
    });
    bucketSort(bucketOfAgent, buckets, mStart, mAgent, threads);
    mPosition.resize(n);
    core::parallelForRanges(n, 4096, threads, [&](core::IndexRange r) {
        for (uint32_t slot = r.begin; slot < r.end; ++slot) {
            const uint32_t a = mAgent[slot];
            const glm::ivec2 c = cellOf(a);
            mKey[slot] = cellKey(c.x, c.y);
            mPosition[slot] = {positions[a].x, positions[a].z};
        }
    });
}

uint32_t SpatialHash::nearest(glm::vec2 p, uint32_t self, float closeRadius, float radius, uint32_t count,
                              NearAgent* out) const {
    // Kept sorted by distance; a later slot at the same distance goes after.
    float distance[kMaxNearest];
    uint32_t slotOf[kMaxNearest];
    uint32_t found = 0;
    auto look = [&](float reach, float lo2, float hi2) {
        forEachRun(p, reach, [&](uint32_t first, uint32_t end, uint32_t row, uint32_t x0, uint32_t span) {
            // Two passes per batch of slots: the tests without branches
            // (which way each goes is a coin toss, and mispredicted branches
            // were most of a query's time), then the few that passed.
            constexpr uint32_t kBatch = 32;
            uint32_t batch[kBatch];
            float batchDistance[kBatch];
            for (uint32_t begin = first; begin < end; begin += kBatch) {
                const uint32_t stop = std::min(end, begin + kBatch);
                uint32_t passed = 0;
                for (uint32_t s = begin; s < stop; ++s) {
                    const glm::vec2 offset = mPosition[s] - p;
                    const float d = offset.x * offset.x + offset.y * offset.y;
                    batch[passed] = s;
                    batchDistance[passed] = d;
                    passed += inRow(mKey[s], row, x0, span) & (d > lo2) & (d <= hi2) & (mAgent[s] != self);
                }
                for (uint32_t k = 0; k < passed; ++k) {
                    const float d = batchDistance[k];
                    if (found == count && d >= distance[count - 1]) continue;
                    uint32_t at = found < count ? found++ : count - 1;
                    for (; at > 0 && distance[at - 1] > d; --at) {
                        distance[at] = distance[at - 1];
                        slotOf[at] = slotOf[at - 1];
                    }
                    distance[at] = d;
                    slotOf[at] = batch[k];
                }
            }
        });
    };
    const float close2 = closeRadius * closeRadius, radius2 = radius * radius;
    if (closeRadius < radius) {
        look(closeRadius, -1.0f, close2);
        if (found < count) look(radius, close2, radius2);
    } else {
        look(radius, -1.0f, radius2);
    }
    for (uint32_t k = 0; k < found; ++k) out[k] = {mAgent[slotOf[k]], distance[k], mPosition[slotOf[k]] - p};
    return found;
}

size_t SpatialHash::bytes() const {
    return (mStart.capacity() + mAgent.capacity() + mKey.capacity()) * sizeof(uint32_t) +
           mPosition.capacity() * sizeof(glm::vec2);
}

} // namespace tessera::crowd
