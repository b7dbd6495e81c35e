#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace tessera::core {
namespace {

// One arena per requested thread count, made on first use and kept for the
// process: creating an arena per call would cost more than the crowd's
// smaller loops. TBB shares its worker threads between arenas.
tbb::task_arena& arenaFor(uint32_t threads) {
    static std::mutex mutex;
    static std::map<uint32_t, std::unique_ptr<tbb::task_arena>> arenas;
    std::lock_guard lock(mutex);
    std::unique_ptr<tbb::task_arena>& arena = arenas[threads];
    if (!arena) arena = std::make_unique<tbb::task_arena>(int(threads));
    return *arena;
}

} // namespace

uint32_t hardwareThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

void parallelForRanges(uint32_t count, uint32_t grain, uint32_t threadCount,
                       const std::function<void(IndexRange)>& body) {
    if (count == 0) return;
    grain = std::max(grain, 1u);
    const uint32_t chunks = (count - 1) / grain + 1;
    // More threads than the hardware has cannot run at once (TBB would
    // refuse the extra workers, noisily); the cut is the same either way.
    const uint32_t threads = std::min(threadCount ? threadCount : hardwareThreads(), hardwareThreads());
    auto run = [&](uint32_t chunk) { body({chunk * grain, std::min(count, (chunk + 1) * grain)}); };
    if (threads == 1 || chunks == 1) {
        for (uint32_t chunk = 0; chunk < chunks; ++chunk) run(chunk);
        return;
    }
    // simple_partitioner with a grain of one chunk: every chunk is its own
    // task, so the cut is exactly the documented one whatever TBB decides.
    arenaFor(threads).execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<uint32_t>(0, chunks, 1),
            [&](const tbb::blocked_range<uint32_t>& r) {
                for (uint32_t chunk = r.begin(); chunk < r.end(); ++chunk) run(chunk);
            },
            tbb::simple_partitioner());
    });
}

void parallelFor(uint32_t count, uint32_t threadCount, const std::function<void(uint32_t)>& body,
                 const std::function<void(uint32_t)>& onProgress) {
    if (!onProgress) {
        parallelForRanges(count, 1, threadCount, [&](IndexRange r) { body(r.begin); });
        return;
    }
    std::atomic<uint32_t> done{0};
    const std::thread::id caller = std::this_thread::get_id();
    parallelForRanges(count, 1, threadCount, [&](IndexRange r) {
        body(r.begin);
        const uint32_t finished = ++done;
        if (std::this_thread::get_id() == caller) onProgress(finished);
    });
}

} // namespace tessera::core
