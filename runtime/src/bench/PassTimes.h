#pragma once
/// @file PassTimes.h
/// The GPU passes of a benchmark row's measured frames, summed per frame and
/// listed per pass: what the rows of --bench characters, subdiv and crowd
/// report of them.

#include "tessera/profiler/ProfilerEvents.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tessera::runtime {

class PassTimes {
public:
    /// Adds `pass`'s duration to its frame's total, to its frame's
    /// selection when `selected` (the passes a row is about) and to its own
    /// list when `listed`.
    void add(const profiler::GpuPassEvent& pass, bool selected, bool listed);

    /// Per frame, every pass summed (ms), in frame order.
    std::vector<double> frameTotals() const { return valuesOf(mFrameMs); }
    /// Per frame that had any, the selected passes summed (ms).
    std::vector<double> selectedTotals() const { return valuesOf(mSelectedMs); }
    /// The frames with a selected pass.
    uint32_t selectedFrames() const { return uint32_t(mSelectedMs.size()); }
    /// Every listed pass with its median ms, in first-recorded order.
    std::vector<std::pair<std::string, double>> passMedians() const;

private:
    static std::vector<double> valuesOf(const std::map<uint64_t, double>& perFrame);

    std::map<uint64_t, double> mFrameMs, mSelectedMs;
    std::vector<std::string> mOrder;
    std::map<std::string, std::vector<double>> mPassMs;
};

} // namespace tessera::runtime
