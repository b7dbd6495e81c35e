#include "BucketSort.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <atomic>

namespace tessera::crowd {
namespace {

constexpr uint32_t kItemGrain = 4096;
constexpr uint32_t kBucketGrain = 16;

} // namespace

void bucketSort(std::span<const uint32_t> bucketOf, uint32_t buckets, std::vector<uint32_t>& start,
                std::vector<uint32_t>& order, uint32_t threads) {
    const uint32_t n = uint32_t(bucketOf.size());
    start.assign(size_t(buckets) + 1, 0);
    order.resize(n);
    // Counts land one place up, so the inclusive prefix sum leaves each
    // bucket's first slot in start[b].
    core::parallelForRanges(n, kItemGrain, threads, [&](core::IndexRange r) {
        for (uint32_t i = r.begin; i < r.end; ++i)
            std::atomic_ref<uint32_t>(start[bucketOf[i] + 1]).fetch_add(1, std::memory_order_relaxed);
    });
    for (uint32_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    // Scattering advances every start to the next bucket's; one shift back
    // restores them.
    core::parallelForRanges(n, kItemGrain, threads, [&](core::IndexRange r) {
        for (uint32_t i = r.begin; i < r.end; ++i)
            order[std::atomic_ref<uint32_t>(start[bucketOf[i]]).fetch_add(1, std::memory_order_relaxed)] = i;
    });
    std::copy_backward(start.begin(), start.end() - 1, start.end());
    start[0] = 0;
    // Threads interleaved their scatters: each bucket back to index order.
    // Crowded buckets cluster (a crowd stands on a few tiles), so the work
    // is spread over the buckets that need it, not over all buckets.
    std::vector<uint32_t> crowded;
    for (uint32_t b = 0; b < buckets; ++b)
        if (start[b + 1] - start[b] > 1) crowded.push_back(b);
    core::parallelForRanges(uint32_t(crowded.size()), kBucketGrain, threads, [&](core::IndexRange r) {
        for (uint32_t k = r.begin; k < r.end; ++k)
            std::sort(order.begin() + start[crowded[k]], order.begin() + start[crowded[k] + 1]);
    });
}

} // namespace tessera::crowd
