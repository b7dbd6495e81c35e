#pragma once
/// @file ParallelFor.h
/// Internal: a minimal fork-join loop for the height-map generator.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

namespace tessera::terrain {

/// Runs body(index) for every index in [0, count) on `threadCount` threads, the
/// calling thread included, and returns when all are done.
///
/// Indices are handed out dynamically, so which thread runs which index varies
/// from run to run: callers must make every index's work independent of the
/// others (disjoint writes, no reads of what another index writes). Then the
/// result is the same for any thread count and any schedule.
///
/// `onProgress(doneCount)` runs on the calling thread only, after each index
/// that thread finishes, so progress callbacks never need locking.
inline void parallelFor(uint32_t count, uint32_t threadCount,
                        const std::function<void(uint32_t)>& body,
                        const std::function<void(uint32_t)>& onProgress = {}) {
    if (count == 0) return;
    std::atomic<uint32_t> next{0};
    std::atomic<uint32_t> done{0};
    auto work = [&](bool reports) {
        for (uint32_t index = next++; index < count; index = next++) {
            body(index);
            uint32_t finished = ++done;
            if (reports && onProgress) onProgress(finished);
        }
    };
    std::vector<std::jthread> helpers;
    uint32_t helperCount = threadCount > 1 ? std::min(threadCount, count) - 1 : 0;
    helpers.reserve(helperCount);
    for (uint32_t t = 0; t < helperCount; ++t) helpers.emplace_back(work, false);
    work(true);
    helpers.clear(); // joins
}

} // namespace tessera::terrain
