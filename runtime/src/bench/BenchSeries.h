#pragma once
/// @file BenchSeries.h
/// The summary the benchmarks give of a series of timings.

#include <algorithm>
#include <numeric>
#include <vector>

namespace tessera::runtime {

struct BenchSeries {
    double median = 0.0, mean = 0.0, min = 0.0, max = 0.0;
};

/// Median (of an even count: the mean of the middle two, as
/// profiler::summarize() defines it), mean, min and max; zeros when empty.
inline BenchSeries summarizeSeries(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return {(values[(n - 1) / 2] + values[n / 2]) / 2.0, std::accumulate(values.begin(), values.end(), 0.0) / double(n),
            values.front(), values.back()};
}

} // namespace tessera::runtime
