#pragma once
/// @file BenchmarkReport.h
/// Summarises a benchmark run recorded in a Profiler: per-pass GPU times,
/// the GPU and CPU frame times, as a JSON file and as a console table.
///
/// Definitions:
/// - A pass's value for a frame is the sum of the durations of all its GPU
///   passes recorded with that frame index (a pass name recorded twice in one
///   frame, e.g. per shadow cascade, counts once with the summed time). Its
///   statistics for the frame are likewise summed.
/// - The GPU frame is the sum of every pass of the frame (not the span from
///   first start to last end: idle gaps are not GPU work).
/// - The CPU frame is beginFrame() to endFrame().
/// - Median of an even count is the mean of the middle two values;
///   statsMedianFrame comes from the lower of those two frames, so it is the
///   statistics of one real frame.
/// Call Profiler::discardFramesBefore() first to drop warm-up frames.

#include "tessera/core/Result.h"
#include "tessera/profiler/Profiler.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tessera::profiler {

/// Distribution of one series of per-frame times. All zero when samples == 0.
struct PassSummary {
    std::string name;
    /// Number of frames with a value.
    size_t samples = 0;
    double minMs = 0.0;
    double medianMs = 0.0;
    double maxMs = 0.0;
    double meanMs = 0.0;
    /// Pipeline statistics of the median frame, when that frame had any.
    std::optional<PipelineStatistics> statsMedianFrame;
};

struct BenchmarkSummary {
    /// One per GPU pass name, in first-recorded order.
    std::vector<PassSummary> passes;
    /// Named "gpu frame": sum of the passes per frame (statistics summed too).
    PassSummary gpuFrame;
    /// Named "cpu frame": from beginFrame()/endFrame().
    PassSummary cpuFrame;
    /// Distinct frame indices seen in GPU passes or CPU frames.
    size_t frames = 0;
};

/// Describes the run; written verbatim to the report's "info".
struct BenchmarkInfo {
    std::string backend;
    std::string device;
    std::string driver;
    std::string scene;
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t warmupFrames = 0;
    /// Frames requested for measurement (BenchmarkSummary::frames says how
    /// many were recorded).
    uint32_t frames = 0;
};

BenchmarkSummary summarize(const Profiler& profiler);

/// The report document (pretty-printed JSON):
/// @code
/// {"format": "tessera-benchmark", "version": 1,
///  "info": {backend, device, driver, scene, width, height, warmupFrames, frames},
///  "frames": <recorded frame count>,
///  "gpuFrame": <pass>, "cpuFrame": <pass>, "passes": [<pass>, ...]}
/// <pass> = {name, samples, minMs, medianMs, maxMs, meanMs,
///           statsMedianFrame: {<PipelineStatistics fields>} | null,
///           frameIndices: [...], frameMs: [...]}   // per frame, ascending
/// @endcode
/// Per-frame lists are taken from `profiler` for each name in `summary`.
/// Milliseconds are written rounded to 6 decimals (1 ns, the timer's unit).
std::string makeBenchmarkJson(const BenchmarkSummary& summary, const BenchmarkInfo& info,
                              const Profiler& profiler);

/// makeBenchmarkJson() written to `path` (created or truncated). Fails with a
/// message naming the file and the OS error.
Status writeBenchmarkJson(const BenchmarkSummary& summary, const BenchmarkInfo& info,
                          const Profiler& profiler, const std::filesystem::path& path);

/// Aligned plain-text table, one line per pass then the GPU and CPU frames:
/// name, min/median/max ms (3 decimals) and the median frame's triangles
/// (trianglesOf(), "-" without statistics), then the frame count.
std::string formatTable(const BenchmarkSummary& summary);

} // namespace tessera::profiler
