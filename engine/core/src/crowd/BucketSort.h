#pragma once
// Internal: the parallel counting sort behind the tile bins.

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::crowd {

/// Sorts the items 0 .. bucketOf.size() - 1 by bucketOf[item] (each below
/// `buckets`) into `order`, ascending item index within a bucket; bucket b
/// holds order[start[b]] .. order[start[b + 1] - 1], the same whatever the
/// thread count. Items that come mostly in bucket order (a few buckets to
/// each chunk of consecutive items) are placed run by run without atomic
/// counters or sorting; others are counted and scattered with atomic
/// counters, each bucket then sorted by item index.
void bucketSort(std::span<const uint32_t> bucketOf, uint32_t buckets, std::vector<uint32_t>& start,
                std::vector<uint32_t>& order, uint32_t threads);

} // namespace tessera::crowd
