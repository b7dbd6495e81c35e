#include "report/ReportWriter.h"

#include "report/BenchInput.h"
#include "report/ReportHtml.h"
#include "report/TraceMerge.h"

#include <chrono>
#include <ctime>
#include <fstream>

namespace tessera::report {
namespace {

namespace fs = std::filesystem;

std::string formatTime(std::time_t t) {
    std::tm utc{};
    gmtime_r(&t, &utc);
    char buffer[64];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &utc);
    return buffer;
}

Status writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out || !(out << text) || !out.flush()) return fail(path.string(), ": cannot write the file");
    return {};
}

/// `target` relative to the folder of `from`, for links that survive moving
/// the report together with its inputs.
std::string relativeLink(const fs::path& target, const fs::path& from) {
    std::error_code ec;
    const fs::path base = fs::absolute(from, ec).parent_path();
    fs::path rel = fs::relative(fs::absolute(target, ec), base, ec);
    return ec || rel.empty() ? fs::absolute(target, ec).string() : rel.generic_string();
}

/// The backend's trace: DIR/bench-<backend>.json, else the file its records
/// name (as the benchmark wrote it: absolute, relative to where it ran, or
/// relative to DIR); "" when none exists.
fs::path findTrace(const InputLayout& layout, const std::vector<BenchRecord>& records, const std::string& backend) {
    std::error_code ec;
    if (fs::exists(layout.trace(backend), ec)) return layout.trace(backend);
    for (const BenchRecord& r : records) {
        if (r.backend != backend || r.trace.empty()) continue;
        const fs::path named = r.trace;
        if (fs::is_regular_file(named, ec)) return named;
        if (named.is_relative() && fs::is_regular_file(layout.dir / named.filename(), ec))
            return layout.dir / named.filename();
    }
    return {};
}

} // namespace

std::string formatUtc(fs::file_time_type time) {
    const auto system = std::chrono::file_clock::to_sys(time);
    return formatTime(std::chrono::system_clock::to_time_t(system));
}

std::string nowUtc() {
    return formatTime(std::time(nullptr));
}

Result<ReportSummary> writeReport(const ReportJob& job) {
    const InputLayout layout{job.inputDir};
    auto records = loadBenchRecords(layout.bench());
    if (!records) return records.error();
    ReportSummary summary;
    summary.records = records->size();

    ReportInputs inputs;
    inputs.records = std::move(records.value());
    inputs.rules = job.rules;
    inputs.camera = job.camera;
    std::error_code ec;
    inputs.measuredAt = !job.measuredAt.empty() ? job.measuredAt
                                                : formatUtc(fs::last_write_time(layout.bench(), ec)) +
                                                      " (the benchmark JSON's modification time)";
    inputs.writtenAt = nowUtc();

    summary.html = job.html;
    summary.trace = job.html.parent_path() / "report-trace.json";
    std::vector<TraceSource> traces;
    for (const std::string& backend : backendsOf(inputs.records)) {
        BackendExtras extras;
        extras.backend = backend;
        const fs::path trace = findTrace(layout, inputs.records, backend);
        if (!trace.empty()) {
            traces.push_back({backend, trace});
            extras.traceLink = relativeLink(trace, job.html);
        } else {
            summary.notes.push_back(layout.trace(backend).string() + ": no trace for " + backend);
        }
        const fs::path shot = layout.screenshot(backend);
        if (fs::exists(shot, ec)) {
            auto image = readPng(shot);
            if (!image) return image.error();
            extras.screenshot = std::move(image.value());
        } else {
            summary.notes.push_back(shot.string() + ": no screenshot of " + backend);
        }
        inputs.backends.push_back(std::move(extras));
    }
    if (job.html.has_parent_path()) {
        fs::create_directories(job.html.parent_path(), ec);
        if (ec) return fail(job.html.parent_path().string(), ": cannot create the folder: ", ec.message());
    }
    if (!traces.empty()) {
        auto merged = mergeTraces(traces);
        if (!merged) return merged.error();
        if (auto w = writeText(summary.trace, merged->json); !w) return w.error();
        summary.traceBytes = merged->json.size();
        inputs.mergedTraceLink = relativeLink(summary.trace, job.html);
    } else {
        summary.trace.clear();
    }
    inputs.notes = summary.notes;
    for (const auto& r : inputs.records) summary.flags += assessRecord(r, job.rules).size();
    const std::string html = renderReport(inputs);
    if (auto w = writeText(job.html, html); !w) return w.error();
    summary.htmlBytes = html.size();
    return summary;
}

} // namespace tessera::report
