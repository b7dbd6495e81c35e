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
// Items per chunk of the sort by runs, and the most buckets one chunk may use.
constexpr uint32_t kChunk = 4096;
constexpr size_t kMaxRuns = 256;

// Any order of items: counted and scattered with atomic counters, then each
// bucket put back into index order.
void sortByCounting(std::span<const uint32_t> bucketOf, uint32_t buckets, std::vector<uint32_t>& start,
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

// Items that come mostly in bucket order already (the crowd's agents, re-sorted
// by tile every few steps): each chunk of consecutive items lists the few
// buckets it uses; every chunk's run of a bucket then has its own place, in
// chunk order, so the scatter needs neither atomic counters nor a sort after.
// False (nothing done) where some chunk uses too many buckets for that.
bool sortByRuns(std::span<const uint32_t> bucketOf, uint32_t buckets, std::vector<uint32_t>& start,
                std::vector<uint32_t>& order, uint32_t threads) {
    struct Run {
        uint32_t bucket = 0, count = 0, next = 0; // next: the run's next slot in order
    };
    const uint32_t n = uint32_t(bucketOf.size());
    std::vector<std::vector<Run>> runs((n + kChunk - 1) / kChunk);
    std::atomic<bool> tooMany{false};
    // The run of `bucket` in `list` (looked for from the end: a new bucket
    // is usually the last one added).
    auto runOf = [](std::vector<Run>& list, uint32_t bucket) -> Run* {
        for (size_t k = list.size(); k-- > 0;)
            if (list[k].bucket == bucket) return &list[k];
        return nullptr;
    };
    core::parallelForRanges(n, kChunk, threads, [&](core::IndexRange r) {
        std::vector<Run>& list = runs[r.begin / kChunk];
        Run* run = nullptr;
        for (uint32_t i = r.begin; i < r.end; ++i) {
            const uint32_t b = bucketOf[i];
            if (!run || run->bucket != b) {
                run = runOf(list, b);
                if (!run) {
                    if (list.size() == kMaxRuns) {
                        tooMany.store(true, std::memory_order_relaxed);
                        return;
                    }
                    run = &list.emplace_back(Run{b, 0, 0});
                }
            }
            ++run->count;
        }
    });
    if (tooMany.load()) return false;
    // Few runs: counted, summed and placed in one pass each, in chunk order.
    start.assign(size_t(buckets) + 1, 0);
    for (const std::vector<Run>& list : runs)
        for (const Run& run : list) start[run.bucket + 1] += run.count;
    for (uint32_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    std::vector<uint32_t> cursor(start.begin(), start.end() - 1);
    for (std::vector<Run>& list : runs)
        for (Run& run : list) run.next = std::exchange(cursor[run.bucket], cursor[run.bucket] + run.count);
    order.resize(n);
    core::parallelForRanges(n, kChunk, threads, [&](core::IndexRange r) {
        std::vector<Run>& list = runs[r.begin / kChunk];
        Run* run = nullptr;
        for (uint32_t i = r.begin; i < r.end; ++i) {
            const uint32_t b = bucketOf[i];
            if (!run || run->bucket != b) run = runOf(list, b);
            order[run->next++] = i;
        }
    });
    return true;
}

} // namespace

void bucketSort(std::span<const uint32_t> bucketOf, uint32_t buckets, std::vector<uint32_t>& start,
                std::vector<uint32_t>& order, uint32_t threads) {
    if (!sortByRuns(bucketOf, buckets, start, order, threads)) sortByCounting(bucketOf, buckets, start, order, threads);
}

} // namespace tessera::crowd
