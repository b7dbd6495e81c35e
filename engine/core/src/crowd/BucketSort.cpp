#include "BucketSort.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <utility>

namespace tessera::crowd {
namespace {

constexpr uint32_t kItemGrain = 4096;
constexpr uint32_t kBucketGrain = 16;
// Buckets per block of the parallel prefix sum and of the crowded list.
constexpr uint32_t kBlock = 16384;

} // namespace

void bucketSort(std::span<const uint32_t> bucketOf, uint32_t buckets, std::vector<uint32_t>& start,
                std::vector<uint32_t>& order, uint32_t threads) {
    const uint32_t n = uint32_t(bucketOf.size());
    // Counts one place up: the exclusive prefix sum then leaves bucket b's
    // first slot in start[b + 1], which the scatter advances to bucket b's
    // end, that is bucket b + 1's first slot: no shift back afterwards.
    start.assign(size_t(buckets) + 1, 0);
    order.resize(n);
    core::parallelForRanges(n, kItemGrain, threads, [&](core::IndexRange r) {
        for (uint32_t i = r.begin; i < r.end; ++i)
            std::atomic_ref<uint32_t>(start[bucketOf[i] + 1]).fetch_add(1, std::memory_order_relaxed);
    });
    // Prefix sum by blocks: each block's total, the totals summed in order
    // (one per block), then each block on its own. A serial pass over a
    // million buckets would be a millisecond that no number of cores
    // shortens.
    const uint32_t blocks = (buckets + 1 + kBlock - 1) / kBlock;
    std::vector<uint32_t> offset(blocks, 0);
    core::parallelForRanges(uint32_t(start.size()), kBlock, threads, [&](core::IndexRange r) {
        uint32_t sum = 0;
        for (uint32_t b = r.begin; b < r.end; ++b) sum += start[b];
        offset[r.begin / kBlock] = sum;
    });
    uint32_t running = 0;
    for (uint32_t& o : offset) running += std::exchange(o, running);
    core::parallelForRanges(uint32_t(start.size()), kBlock, threads, [&](core::IndexRange r) {
        uint32_t sum = offset[r.begin / kBlock];
        for (uint32_t b = r.begin; b < r.end; ++b) sum += std::exchange(start[b], sum);
    });
    core::parallelForRanges(n, kItemGrain, threads, [&](core::IndexRange r) {
        for (uint32_t i = r.begin; i < r.end; ++i)
            order[std::atomic_ref<uint32_t>(start[bucketOf[i] + 1]).fetch_add(1, std::memory_order_relaxed)] = i;
    });
    // Threads interleaved their scatters: each bucket back to index order.
    // Crowded buckets cluster (a crowd stands on a few tiles), so the work
    // is spread over the buckets that need it, not over all buckets; the
    // list of them is gathered by blocks, in parallel, and joined in order.
    std::vector<std::vector<uint32_t>> crowdedIn((buckets + kBlock - 1) / kBlock);
    core::parallelForRanges(buckets, kBlock, threads, [&](core::IndexRange r) {
        std::vector<uint32_t>& list = crowdedIn[r.begin / kBlock];
        for (uint32_t b = r.begin; b < r.end; ++b)
            if (start[b + 1] - start[b] > 1) list.push_back(b);
    });
    std::vector<uint32_t> crowded;
    for (const std::vector<uint32_t>& list : crowdedIn) crowded.insert(crowded.end(), list.begin(), list.end());
    core::parallelForRanges(uint32_t(crowded.size()), kBucketGrain, threads, [&](core::IndexRange r) {
        for (uint32_t k = r.begin; k < r.end; ++k)
            std::sort(order.begin() + start[crowded[k]], order.begin() + start[crowded[k] + 1]);
    });
}

} // namespace tessera::crowd
