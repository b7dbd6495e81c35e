#pragma once
/// @file ParallelFor.h
/// The one parallel loop of the code base. Every module that spreads work
/// over cores (terrain generation and detail, the crowd simulation, the
/// content tools) calls it, so there is one thread pool (oneTBB's) and one
/// place to tune or instrument.
///
/// Determinism rule: indices are handed out dynamically, so which thread runs
/// which index varies from run to run. Callers make every index's work
/// independent of the others (disjoint writes, no reads of what another index
/// of the same loop writes); then the result is the same for any thread count
/// and any schedule, which the crowd's and the terrain generator's
/// determinism tests check with 1, 2 and 8 threads.

#include <cstdint>
#include <functional>

namespace tessera::core {

/// A half-open range of loop indices, [begin, end).
struct IndexRange {
    uint32_t begin = 0;
    uint32_t end = 0;
};

/// Number of hardware threads (at least 1): what `threadCount = 0` means.
uint32_t hardwareThreads();

/// Runs `body` over [0, count) cut into consecutive ranges of `grain`
/// indices (the last one shorter), on at most `threadCount` threads, the
/// calling thread included (0: hardwareThreads(); 1: serially on the calling
/// thread, no pool involved), and returns when all ranges are done. The cut
/// does not depend on the thread count. `grain` 0 is taken as 1.
void parallelForRanges(uint32_t count, uint32_t grain, uint32_t threadCount,
                       const std::function<void(IndexRange)>& body);

/// Runs body(index) for every index in [0, count), as parallelForRanges with
/// a grain of one. `onProgress(doneCount)` runs on the calling thread only,
/// after each index that thread finishes (so progress callbacks never need
/// locking); doneCount counts indices finished by any thread.
void parallelFor(uint32_t count, uint32_t threadCount, const std::function<void(uint32_t)>& body,
                 const std::function<void(uint32_t)>& onProgress = {});

} // namespace tessera::core
