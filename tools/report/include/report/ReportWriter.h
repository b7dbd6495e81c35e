#pragma once
/// @file ReportWriter.h
/// Reads a report's inputs from a folder and writes the HTML report and the
/// merged trace: what `tessera-report` does after (or without) `--run`.

#include "report/Plausibility.h"

#include "tessera/core/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tessera::report {

struct ReportJob {
    /// The inputs: bench.json (required), bench-<backend>.json traces (else
    /// the trace a backend's records name) and screenshot-<backend>.png
    /// images (each optional: a missing one is a note in the report and on
    /// stderr).
    std::filesystem::path inputDir;
    /// The HTML file; the merged trace goes beside it as report-trace.json.
    std::filesystem::path html;
    std::string camera;     ///< the screenshots' camera, shown when known
    std::string measuredAt; ///< "" for the bench JSON's modification time
    PlausibilityRules rules;
};

struct ReportSummary {
    std::filesystem::path html;
    std::filesystem::path trace; ///< empty when no backend had a trace
    uintmax_t htmlBytes = 0;
    uintmax_t traceBytes = 0;
    size_t records = 0;
    size_t flags = 0;
    std::vector<std::string> notes; ///< missing optional inputs
};

/// Writes the report. Fails with one line naming the file when bench.json is
/// missing or malformed, a trace or screenshot that exists cannot be read, or
/// an output cannot be written.
Result<ReportSummary> writeReport(const ReportJob& job);

/// A time as "2026-11-25 18:40 UTC".
std::string formatUtc(std::filesystem::file_time_type time);
std::string nowUtc();

} // namespace tessera::report
