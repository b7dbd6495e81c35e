#include "bench/PassTimes.h"

#include "bench/BenchSeries.h"

namespace tessera::runtime {

void PassTimes::add(const profiler::GpuPassEvent& pass, bool selected, bool listed) {
    const double ms = double(pass.durationNs) / 1e6;
    mFrameMs[pass.frame] += ms;
    if (selected) mSelectedMs[pass.frame] += ms;
    if (!listed) return;
    auto& durations = mPassMs[pass.name];
    if (durations.empty()) mOrder.push_back(pass.name);
    durations.push_back(ms);
}

std::vector<std::pair<std::string, double>> PassTimes::passMedians() const {
    std::vector<std::pair<std::string, double>> medians;
    for (const std::string& name : mOrder) medians.emplace_back(name, summarizeSeries(mPassMs.at(name)).median);
    return medians;
}

std::vector<double> PassTimes::valuesOf(const std::map<uint64_t, double>& perFrame) {
    std::vector<double> values;
    for (const auto& [frame, ms] : perFrame) values.push_back(ms);
    return values;
}

} // namespace tessera::runtime
