#include "tessera/profiler/BenchmarkReport.h"

#include "TextFile.h"
#include "tessera/core/JsonWriter.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <string_view>
#include <unordered_map>
#include <utility>

namespace tessera::profiler {
namespace {

/// One frame's total for a series. Summed in integer nanoseconds so that the
/// order of addition cannot change the result.
struct FrameTotal {
    uint64_t ns = 0;
    std::optional<PipelineStatistics> stats;

    void add(uint64_t durationNs, const std::optional<PipelineStatistics>& passStats) {
        ns += durationNs;
        if (!passStats) return;
        if (!stats) stats.emplace();
        *stats += *passStats;
    }
};

/// Per-frame totals of one series, ascending by frame index.
struct Series {
    std::string name;
    std::map<uint64_t, FrameTotal> frames;
};

struct AllSeries {
    std::vector<Series> passes;
    Series gpuFrame{"gpu frame", {}};
    Series cpuFrame{"cpu frame", {}};
    size_t frameCount = 0;
};

AllSeries collect(const Profiler& profiler) {
    AllSeries all;
    std::unordered_map<std::string, size_t> passIndex;
    std::set<uint64_t> frameIndices;
    for (const GpuPassEvent& pass : profiler.gpuPasses()) {
        auto [it, inserted] = passIndex.try_emplace(pass.name, all.passes.size());
        if (inserted) all.passes.push_back({pass.name, {}});
        all.passes[it->second].frames[pass.frame].add(pass.durationNs, pass.stats);
        all.gpuFrame.frames[pass.frame].add(pass.durationNs, pass.stats);
        frameIndices.insert(pass.frame);
    }
    for (const FrameEvent& frame : profiler.frameEvents()) {
        all.cpuFrame.frames[frame.frame].add(frame.durationNs, std::nullopt);
        frameIndices.insert(frame.frame);
    }
    all.frameCount = frameIndices.size();
    return all;
}

double toMs(uint64_t ns) { return static_cast<double>(ns) / 1e6; }

PassSummary summarizeSeries(const Series& series) {
    PassSummary summary;
    summary.name = series.name;
    summary.samples = series.frames.size();
    if (series.frames.empty()) return summary;

    std::vector<const FrameTotal*> sorted;
    for (const auto& [frame, total] : series.frames) sorted.push_back(&total);
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const FrameTotal* a, const FrameTotal* b) { return a->ns < b->ns; });
    size_t n = sorted.size();
    const FrameTotal& lowerMiddle = *sorted[(n - 1) / 2];
    const FrameTotal& upperMiddle = *sorted[n / 2];
    uint64_t totalNs = std::accumulate(sorted.begin(), sorted.end(), uint64_t{0},
                                       [](uint64_t sum, const FrameTotal* t) { return sum + t->ns; });
    summary.minMs = toMs(sorted.front()->ns);
    summary.maxMs = toMs(sorted.back()->ns);
    summary.medianMs = toMs(lowerMiddle.ns + upperMiddle.ns) / 2.0;
    summary.meanMs = toMs(totalNs) / static_cast<double>(n);
    summary.statsMedianFrame = lowerMiddle.stats;
    // Task and mesh invocations are counted on some frames only
    // (Profiler::requestMeshInvocationCount): take the latest frame's that has them.
    if (summary.statsMedianFrame)
        for (auto it = series.frames.rbegin(); it != series.frames.rend(); ++it) {
            const auto& stats = it->second.stats;
            if (!stats || (stats->taskShaderInvocations == 0 && stats->meshShaderInvocations == 0)) continue;
            summary.statsMedianFrame->taskShaderInvocations = stats->taskShaderInvocations;
            summary.statsMedianFrame->meshShaderInvocations = stats->meshShaderInvocations;
            break;
        }
    return summary;
}

// Six decimals of a millisecond is a nanosecond, the timer's resolution;
// more would only print the noise of double arithmetic (0.9025000000000001).
constexpr int kMsDecimals = 6;

void writeMs(JsonWriter& json, std::string_view key, double ms) {
    json.key(key);
    json.valueFixed(ms, kMsDecimals);
}

void writeStatistics(JsonWriter& json, const std::optional<PipelineStatistics>& stats) {
    if (!stats) {
        json.null();
        return;
    }
    json.beginObject();
    forEachPipelineStatistic([&](const char* name, uint64_t PipelineStatistics::*field) {
        json.keyValue(name, (*stats).*field);
    });
    json.endObject();
}

void writePass(JsonWriter& json, const PassSummary& summary, const Series* series) {
    json.beginObject();
    json.keyValue("name", summary.name);
    json.keyValue("samples", summary.samples);
    writeMs(json, "minMs", summary.minMs);
    writeMs(json, "medianMs", summary.medianMs);
    writeMs(json, "maxMs", summary.maxMs);
    writeMs(json, "meanMs", summary.meanMs);
    json.key("statsMedianFrame");
    writeStatistics(json, summary.statsMedianFrame);
    json.key("frameIndices");
    json.beginArray();
    if (series != nullptr) {
        for (const auto& [frame, total] : series->frames) json.value(frame);
    }
    json.endArray();
    json.key("frameMs");
    json.beginArray();
    if (series != nullptr) {
        for (const auto& [frame, total] : series->frames) json.valueFixed(toMs(total.ns), kMsDecimals);
    }
    json.endArray();
    json.endObject();
}

void writeInfo(JsonWriter& json, const BenchmarkInfo& info) {
    json.key("info");
    json.beginObject();
    json.keyValue("backend", info.backend);
    json.keyValue("device", info.device);
    json.keyValue("driver", info.driver);
    json.keyValue("scene", info.scene);
    json.keyValue("width", info.width);
    json.keyValue("height", info.height);
    json.keyValue("warmupFrames", info.warmupFrames);
    json.keyValue("frames", info.frames);
    json.endObject();
}

} // namespace

BenchmarkSummary summarize(const Profiler& profiler) {
    AllSeries all = collect(profiler);
    BenchmarkSummary summary;
    summary.passes.reserve(all.passes.size());
    for (const Series& series : all.passes) summary.passes.push_back(summarizeSeries(series));
    summary.gpuFrame = summarizeSeries(all.gpuFrame);
    summary.cpuFrame = summarizeSeries(all.cpuFrame);
    summary.frames = all.frameCount;
    return summary;
}

std::string makeBenchmarkJson(const BenchmarkSummary& summary, const BenchmarkInfo& info,
                              const Profiler& profiler) {
    AllSeries all = collect(profiler);
    auto findPass = [&](const std::string& name) -> const Series* {
        auto it = std::find_if(all.passes.begin(), all.passes.end(),
                               [&](const Series& s) { return s.name == name; });
        return it == all.passes.end() ? nullptr : &*it;
    };

    JsonWriter json(/*pretty=*/true);
    json.beginObject();
    // Lets comparison scripts reject reports they do not understand.
    json.keyValue("format", "tessera-benchmark");
    json.keyValue("version", 1);
    writeInfo(json, info);
    json.keyValue("frames", summary.frames);
    json.key("gpuFrame");
    writePass(json, summary.gpuFrame, &all.gpuFrame);
    json.key("cpuFrame");
    writePass(json, summary.cpuFrame, &all.cpuFrame);
    json.key("passes");
    json.beginArray();
    for (const PassSummary& pass : summary.passes) writePass(json, pass, findPass(pass.name));
    json.endArray();
    json.endObject();
    return std::move(json).take();
}

Status writeBenchmarkJson(const BenchmarkSummary& summary, const BenchmarkInfo& info,
                          const Profiler& profiler, const std::filesystem::path& path) {
    return detail::writeTextFile(path, makeBenchmarkJson(summary, info, profiler));
}

} // namespace tessera::profiler
