#pragma once
/// @file Plausibility.h
/// Which GPU timings the report cannot present as facts.
///
/// GPU pass times come from timestamp queries. On a real GPU they bracket the
/// pass's work; on a CPU implementation (lavapipe) the rasteriser runs
/// deferred, and a timestamp pair may close before the pass's triangles are
/// drawn: r2vb's main terrain pass once read 0.13 ms inside a 30 ms frame.
/// The wall-clock (CPU) frame of the same frames is the check: it includes
/// the wait for the previous frame, so over steady frames it cannot be
/// shorter than the GPU's own frame, and on a CPU device, where the "GPU"
/// work runs on the same cores, the pass that draws every triangle cannot be
/// a vanishing share of it.

#include "report/BenchInput.h"

#include <string>
#include <vector>

namespace tessera::report {

/// The thresholds (docs/BACKENDS.md, "The comparison report").
struct PlausibilityRules {
    /// On a CPU device, the main terrain pass must take at least this share
    /// of the wall-clock frame.
    double minMainPassShare = 0.02;
    /// On a CPU device, the GPU passes together must account for at least
    /// this share of the wall-clock frame; where they do not, the main
    /// terrain pass is flagged, the one pass that can hide that much work.
    /// (Measured on lavapipe at 320x180: hulldomain and streamout 67% to
    /// 100%, r2vb's adaptive rows 34% to 40%, its close continuous row 2%.)
    double minGpuFrameShare = 0.5;
    /// On any device, the GPU frame may exceed the wall-clock frame by at most
    /// this factor (plus `slackMs`, for timer granularity).
    double maxGpuOverFrame = 1.25;
    double slackMs = 0.05;
};

/// True for a device that runs "GPU" work on the CPU (lavapipe/llvmpipe,
/// SwiftShader), by its name.
bool isCpuDevice(const std::string& deviceName);

/// One timing the report marks instead of charting as fact.
struct TimingFlag {
    std::string pass;   ///< the pass's name, or "" for the whole GPU frame
    std::string reason; ///< one sentence with the figures
};

/// The flags of one record under `rules`.
std::vector<TimingFlag> assessRecord(const BenchRecord& record, const PlausibilityRules& rules = {});

/// True when `flags` mark pass `name` (or the whole frame, for "").
bool isFlagged(const std::vector<TimingFlag>& flags, const std::string& name);

} // namespace tessera::report
