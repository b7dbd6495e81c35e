#include "window/FrameStats.h"

#include <numeric>

namespace tessera::runtime {

void FrameStats::push(std::deque<float>& history, float value) {
    history.push_back(value);
    while (history.size() > kHistory) history.pop_front();
}

void FrameStats::addCpuFrame(float ms) { push(mCpuHistory, ms); }

float FrameStats::cpuMeanMs() const {
    if (mCpuHistory.empty()) return 0.0f;
    return std::accumulate(mCpuHistory.begin(), mCpuHistory.end(), 0.0f) / float(mCpuHistory.size());
}

void FrameStats::addGpuPasses(std::span<const profiler::GpuPassEvent> passes) {
    uint64_t newest = 0;
    bool found = false;
    for (const auto& p : passes)
        if (!found || p.frame > newest) {
            newest = p.frame;
            found = true;
        }
    if (!found || (mAnyGpuFrame && newest <= mGpuFrame)) return;
    mGpuFrame = newest;
    mAnyGpuFrame = true;
    mPasses.clear();
    mStatistics = {};
    mHasStatistics = false;
    float total = 0.0f;
    for (const auto& p : passes) {
        if (p.frame != newest) continue;
        const float ms = float(p.durationNs) * 1e-6f;
        mPasses.push_back({p.name, ms});
        total += ms;
        if (!p.stats) continue;
        mHasStatistics = true;
        profiler::forEachPipelineStatistic(
            [&](const char*, auto member) { mStatistics.*member += (*p.stats).*member; });
    }
    push(mGpuHistory, total);
}

} // namespace tessera::runtime
