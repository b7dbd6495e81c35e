#pragma once
/// @file FrameStats.h
/// What the window's overlay shows of recent frames: the CPU frame time and
/// the newest GPU frame the profiler has resolved (per-pass times, pipeline
/// statistics), with a short history for the graphs. Pure CPU, fed from the
/// profiler's records.

#include "tessera/profiler/PipelineStatistics.h"
#include "tessera/profiler/ProfilerEvents.h"

#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <vector>

namespace tessera::runtime {

class FrameStats {
public:
    /// Frames of history the graphs show.
    static constexpr size_t kHistory = 240;

    struct Pass {
        std::string name;
        float ms = 0.0f;
    };

    /// Adds one CPU frame's wall time.
    void addCpuFrame(float ms);
    /// Takes the newest frame among `passes` that is newer than the last one
    /// taken: its passes (in recording order), their sum, and the pipeline
    /// statistics summed over the passes that have them. Older frames are
    /// ignored; a frame is complete once the profiler holds it, since the GPU
    /// layer resolves a frame's queries together.
    void addGpuPasses(std::span<const profiler::GpuPassEvent> passes);

    const std::vector<Pass>& passes() const { return mPasses; }
    const profiler::PipelineStatistics& statistics() const { return mStatistics; }
    bool hasStatistics() const { return mHasStatistics; }
    float gpuMs() const { return mGpuHistory.empty() ? 0.0f : mGpuHistory.back(); }
    float cpuMs() const { return mCpuHistory.empty() ? 0.0f : mCpuHistory.back(); }
    /// Mean CPU frame time over the history (a steadier read than the last).
    float cpuMeanMs() const;
    uint64_t gpuFrame() const { return mGpuFrame; }
    const std::deque<float>& gpuHistory() const { return mGpuHistory; }
    const std::deque<float>& cpuHistory() const { return mCpuHistory; }

private:
    static void push(std::deque<float>& history, float value);

    std::vector<Pass> mPasses;
    profiler::PipelineStatistics mStatistics;
    bool mHasStatistics = false;
    uint64_t mGpuFrame = 0;
    bool mAnyGpuFrame = false;
    std::deque<float> mGpuHistory;
    std::deque<float> mCpuHistory;
};

} // namespace tessera::runtime
