#pragma once
/// @file ReportHtml.h
/// The comparison report: one self-contained HTML file (inline SVG charts,
/// images as data: URIs, no script), docs/BACKENDS.md "The comparison report".

#include "report/BenchInput.h"
#include "report/Plausibility.h"

#include "tessera/core/ImageFile.h"

#include <optional>
#include <string>
#include <vector>

namespace tessera::report {

/// What the report shows of one backend besides its records.
struct BackendExtras {
    std::string backend;
    std::optional<Rgba8Image> screenshot; ///< the backend's image of the report's camera
    std::string traceLink;                ///< its trace, relative to the HTML ("" if none)
};

struct ReportInputs {
    std::vector<BenchRecord> records;
    std::vector<BackendExtras> backends; ///< report order, reference first
    std::string measuredAt;              ///< when the benchmark ran (UTC)
    std::string writtenAt;               ///< when the report was written (UTC)
    std::string mergedTraceLink;         ///< the merged trace, relative ("" if none)
    std::string camera;                  ///< the screenshots' --camera ("" if unknown)
    std::vector<std::string> notes;      ///< missing inputs and the like, shown on top
    PlausibilityRules rules;
};

/// The report's HTML. Every chart is an `<svg class="chart" data-chart=ID>`
/// whose marks carry `data-series` (backend or pass name) and `data-row`, so
/// a test can find the series it expects; flagged timings are drawn hatched
/// (`class="flagged"`) and listed with their reasons.
std::string renderReport(const ReportInputs& inputs);

/// Escapes text for HTML element content and attribute values.
std::string escapeHtml(const std::string& text);

} // namespace tessera::report
