#include "tessera/profiler/TraceWriter.h"

#include "TextFile.h"
#include "tessera/core/JsonWriter.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace tessera::profiler {
namespace {

constexpr int kPid = 1;

/// A complete event on one track, whatever it came from.
struct Slice {
    std::string_view name;
    const char* category;
    uint32_t tid;
    uint64_t frame;
    uint64_t startNs;
    uint64_t durationNs;
    const PipelineStatistics* stats;
};

struct CounterPoint {
    std::string_view name;
    uint64_t timeNs;
    double value;
};

/// Trace Event Format times are microseconds. Three decimals keep every
/// nanosecond; fixed notation keeps the file readable and spares importers
/// exponents ("1e+07"), which not every hand-written reader handles.
void writeMicroseconds(JsonWriter& json, std::string_view key, uint64_t ns) {
    json.key(key);
    json.valueFixed(static_cast<double>(ns) / 1000.0, 3);
}

uint32_t cpuTid(uint32_t threadId) { return threadId + 1; }

/// A metadata ("M") event: `{"name":event, ..., "args":{argKey: arg}}`.
template <class T>
void writeMetadataEvent(JsonWriter& json, std::string_view event, uint32_t tid,
                        std::string_view argKey, const T& arg) {
    json.beginObject();
    json.keyValue("name", event);
    json.keyValue("ph", "M");
    json.keyValue("pid", kPid);
    json.keyValue("tid", tid);
    json.key("args");
    json.beginObject();
    json.keyValue(argKey, arg);
    json.endObject();
    json.endObject();
}

void writeTrack(JsonWriter& json, uint32_t tid, std::string_view name, int sortIndex) {
    writeMetadataEvent(json, "thread_name", tid, "name", name);
    writeMetadataEvent(json, "thread_sort_index", tid, "sort_index", sortIndex);
}

void writeMetadataEvents(JsonWriter& json, const std::set<uint32_t>& cpuThreads, bool hasGpu,
                         const TraceMetadata& metadata) {
    writeMetadataEvent(json, "process_name", 0, "name", metadata.application);
    // Sort order: CPU main, GPU, workers, so CPU and GPU frames sit side by side.
    for (uint32_t thread : cpuThreads) {
        std::string name = thread == 0 ? "CPU main" : "CPU worker " + std::to_string(thread);
        writeTrack(json, cpuTid(thread), name, thread == 0 ? 0 : static_cast<int>(thread) + 1);
    }
    if (hasGpu) {
        std::string name = metadata.device.empty() ? "GPU" : "GPU (" + metadata.device + ")";
        writeTrack(json, kGpuTraceTid, name, 1);
    }
}

void writeSlice(JsonWriter& json, const Slice& slice) {
    json.beginObject();
    json.keyValue("name", slice.name);
    json.keyValue("cat", slice.category);
    json.keyValue("ph", "X");
    json.keyValue("pid", kPid);
    json.keyValue("tid", slice.tid);
    writeMicroseconds(json, "ts", slice.startNs);
    writeMicroseconds(json, "dur", slice.durationNs);
    json.key("args");
    json.beginObject();
    json.keyValue("frame", slice.frame);
    if (slice.stats != nullptr) {
        forEachPipelineStatistic([&](const char* name, uint64_t PipelineStatistics::*field) {
            json.keyValue(name, (*slice.stats).*field);
        });
        json.keyValue(kTrianglesCounter, trianglesOf(*slice.stats));
    }
    json.endObject();
    json.endObject();
}

void writeCounter(JsonWriter& json, const CounterPoint& point) {
    json.beginObject();
    json.keyValue("name", point.name);
    json.keyValue("ph", "C");
    json.keyValue("pid", kPid);
    writeMicroseconds(json, "ts", point.timeNs);
    json.key("args");
    json.beginObject();
    json.keyValue("value", point.value);
    json.endObject();
    json.endObject();
}

/// The per-frame counters derived from GPU pass statistics.
void appendDerivedCounters(const std::vector<GpuPassEvent>& passes, std::vector<CounterPoint>& out) {
    struct FrameTotals {
        uint64_t firstStartNs = UINT64_MAX;
        uint64_t triangles = 0;
        uint64_t tessEvaluations = 0;
    };
    std::map<uint64_t, FrameTotals> frames;
    for (const GpuPassEvent& pass : passes) {
        if (!pass.stats) continue;
        FrameTotals& totals = frames[pass.frame];
        totals.firstStartNs = std::min(totals.firstStartNs, pass.startNs);
        totals.triangles += trianglesOf(*pass.stats);
        totals.tessEvaluations += pass.stats->tessEvaluationInvocations;
    }
    for (const auto& [frame, totals] : frames) {
        out.push_back({kTrianglesCounter, totals.firstStartNs, static_cast<double>(totals.triangles)});
        out.push_back({kTessEvaluationCounter, totals.firstStartNs,
                       static_cast<double>(totals.tessEvaluations)});
    }
}

void writeTopLevelMetadata(JsonWriter& json, const TraceMetadata& metadata) {
    json.key("metadata");
    json.beginObject();
    json.keyValue("application", metadata.application);
    json.keyValue("backend", metadata.backend);
    json.keyValue("device", metadata.device);
    json.keyValue("driver", metadata.driver);
    json.keyValue("width", metadata.width);
    json.keyValue("height", metadata.height);
    json.endObject();
}

} // namespace

std::string makeChromeTrace(const Profiler& profiler, const TraceMetadata& metadata) {
    // Copies: the slices below point into them, and recording may continue.
    std::vector<FrameEvent> frames = profiler.frameEvents();
    std::vector<CpuEvent> cpuEvents = profiler.cpuEvents();
    std::vector<GpuPassEvent> gpuPasses = profiler.gpuPasses();
    std::vector<CounterSample> samples = profiler.counters();

    std::set<uint32_t> cpuThreads;
    std::vector<Slice> slices;
    slices.reserve(frames.size() + cpuEvents.size() + gpuPasses.size());
    for (const FrameEvent& f : frames) {
        cpuThreads.insert(f.threadId);
        slices.push_back({"frame", "frame", cpuTid(f.threadId), f.frame, f.startNs, f.durationNs, nullptr});
    }
    for (const CpuEvent& e : cpuEvents) {
        cpuThreads.insert(e.threadId);
        slices.push_back({e.name, "cpu", cpuTid(e.threadId), e.frame, e.startNs, e.durationNs, nullptr});
    }
    for (const GpuPassEvent& p : gpuPasses) {
        const PipelineStatistics* stats = p.stats ? &*p.stats : nullptr;
        slices.push_back({p.name, "gpu", kGpuTraceTid, p.frame, p.startNs, p.durationNs, stats});
    }
    // Parents before children: scopes are recorded inner-first, and an
    // importer given a child before its parent at the same timestamp may
    // nest them the wrong way round.
    std::stable_sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) {
        if (a.tid != b.tid) return a.tid < b.tid;
        if (a.startNs != b.startNs) return a.startNs < b.startNs;
        return a.durationNs > b.durationNs;
    });

    std::vector<CounterPoint> counters;
    counters.reserve(samples.size());
    for (const CounterSample& s : samples) counters.push_back({s.name, s.timeNs, s.value});
    appendDerivedCounters(gpuPasses, counters);
    std::stable_sort(counters.begin(), counters.end(),
                     [](const CounterPoint& a, const CounterPoint& b) { return a.timeNs < b.timeNs; });

    JsonWriter json;
    json.beginObject();
    json.keyValue("displayTimeUnit", "ms");
    json.key("traceEvents");
    json.beginArray();
    writeMetadataEvents(json, cpuThreads, !gpuPasses.empty(), metadata);
    for (const Slice& slice : slices) writeSlice(json, slice);
    for (const CounterPoint& point : counters) writeCounter(json, point);
    json.endArray();
    writeTopLevelMetadata(json, metadata);
    json.endObject();
    return std::move(json).take();
}

Status writeChromeTrace(const Profiler& profiler, const std::filesystem::path& path,
                        const TraceMetadata& metadata) {
    return detail::writeTextFile(path, makeChromeTrace(profiler, metadata));
}

} // namespace tessera::profiler
