#pragma once
/// @file TraceWriter.h
/// Writes a Profiler's records as a Chrome Trace Event Format file, which
/// Perfetto UI (ui.perfetto.dev) and chrome://tracing open directly.
///
/// Layout of the file (JSON object form):
/// @code
/// {"displayTimeUnit":"ms", "traceEvents":[...],
///  "metadata":{"application":..,"backend":..,"device":..,"driver":..,"width":..,"height":..}}
/// @endcode
/// displayTimeUnit comes first because Perfetto reads the file in chunks and
/// ignores a unit that arrives after the events; Perfetto also stops at an
/// unknown top-level key, so the file holds only these three.
/// - One process (pid 1), named TraceMetadata::application.
/// - One thread track per CPU thread that recorded anything: "CPU main" for
///   thread id 0, "CPU worker N" for thread id N (tid = N + 1), holding the
///   frames ("frame", category "frame") and CpuScopes (category "cpu").
/// - One track "GPU (<device>)" (just "GPU" when the device is unknown;
///   tid kGpuTraceTid) holding the GPU passes (category "gpu"). Tracks are
///   ordered CPU main, GPU, workers.
/// - Slices are complete events ("ph":"X") with `ts`/`dur` in microseconds
///   in fixed notation with up to three decimals (1,500,000 ns -> `1500`,
///   1,234 ns -> `1.234`), so nanoseconds survive and no exponent appears.
///   `args` holds the frame index; GPU passes with statistics also hold every
///   PipelineStatistics field by name and "triangles" (trianglesOf()).
/// - Counters are counter events ("ph":"C", `args` {"value": v}), one per
///   recorded CounterSample, plus two derived per frame from GPU pass
///   statistics, stamped at the frame's first GPU pass:
///   - kTrianglesCounter: sum over the frame's passes of trianglesOf(), i.e.
///     primitives leaving the clipper (see PipelineStatistics.h for the
///     fallback when a device reports no clipping counts);
///   - kTessEvaluationCounter: sum of tessEvaluationInvocations.
///   A recorded counter with one of these names would share their track.
///
/// Viewers nest slices of one track by time, so a CpuScope that straddles
/// endFrame()/beginFrame() shows as misnested; GPU passes of one queue never
/// overlap, passes from several queues on the one GPU track would.

#include "tessera/core/Result.h"
#include "tessera/profiler/Profiler.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace tessera::profiler {

/// Describes the run; written to the trace's "metadata" and track names.
struct TraceMetadata {
    std::string application = "tessera";
    std::string backend;
    std::string device;
    std::string driver;
    uint32_t width = 0;
    uint32_t height = 0;
};

/// Name of the derived per-frame triangle counter.
inline constexpr std::string_view kTrianglesCounter = "triangles";
/// Name of the derived per-frame tessellation-evaluation counter.
inline constexpr std::string_view kTessEvaluationCounter = "tess-evaluation invocations";
/// Trace tid of the GPU track (CPU threads use their thread id + 1).
inline constexpr uint32_t kGpuTraceTid = 1'000'000;

/// Builds the trace document for `profiler`'s current records.
std::string makeChromeTrace(const Profiler& profiler, const TraceMetadata& metadata);

/// makeChromeTrace() written to `path` (created or truncated). Fails with a
/// message naming the file and the OS error.
Status writeChromeTrace(const Profiler& profiler, const std::filesystem::path& path,
                        const TraceMetadata& metadata);

} // namespace tessera::profiler
