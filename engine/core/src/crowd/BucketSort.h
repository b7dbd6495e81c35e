#pragma once
// Internal: the parallel counting sort behind the spatial hash and the tile
// bins.

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::crowd {

/// Sorts the items 0 .. bucketOf.size() - 1 by bucketOf[item] (each below
/// `buckets`) into `order`, ascending item index within a bucket; bucket b
/// holds order[start[b]] .. order[start[b + 1] - 1]. Counting and scattering
/// run on `threads` threads with atomic counters, and each bucket is then
/// sorted by item index, so the result is the same whatever the thread
/// count or interleaving. Every pass over the items or the buckets is
/// parallel (the prefix sum by blocks).
void bucketSort(std::span<const uint32_t> bucketOf, uint32_t buckets, std::vector<uint32_t>& start,
                std::vector<uint32_t>& order, uint32_t threads);

} // namespace tessera::crowd
