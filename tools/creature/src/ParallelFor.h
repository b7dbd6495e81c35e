#pragma once
// A static-partition parallel loop (internal header). Each index is handled
// exactly once and writes only its own outputs, so results do not depend on
// the thread count or scheduling.

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace tessera::creature {

/// Calls body(begin, end) over [0, count) in contiguous blocks, on up to
/// hardware_concurrency threads (the calling thread included).
template <class Body>
void parallelFor(size_t count, const Body& body) {
    size_t threads = std::max<size_t>(1, std::min<size_t>(std::thread::hardware_concurrency(), 16));
    if (count < 1024 || threads == 1) {
        body(size_t{0}, count);
        return;
    }
    size_t block = (count + threads - 1) / threads;
    std::vector<std::thread> workers;
    for (size_t t = 1; t < threads; ++t) {
        size_t begin = t * block, end = std::min(count, begin + block);
        if (begin < end) workers.emplace_back([&body, begin, end] { body(begin, end); });
    }
    body(size_t{0}, std::min(count, block));
    for (std::thread& w : workers) w.join();
}

} // namespace tessera::creature
