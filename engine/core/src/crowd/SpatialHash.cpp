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

size_t SpatialHash::bytes() const {
    return (mStart.capacity() + mAgent.capacity() + mKey.capacity()) * sizeof(uint32_t) +
           mPosition.capacity() * sizeof(glm::vec2);
}

} // namespace tessera::crowd
