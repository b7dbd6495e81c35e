#include "TerrainBenchmark.h"

#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/World.h"
#include "BenchOutputs.h"
#include "tessera/runtime/RenderSession.h"
#include "TerrainBenchReport.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/Instance.h"
#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/profiler/TraceWriter.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace tessera::runtime {

namespace {

struct BenchView {
    const char* name;
    scene::CameraPose pose;
};

scene::CameraPose lookFrom(const glm::vec3& eye, const glm::vec2& target, float pitchDegrees) {
    const glm::vec2 d = target - glm::vec2(eye.x, eye.z);
    return {eye, std::atan2(-d.x, -d.y), glm::radians(pitchDegrees)};
}

/// Table 2's two views: the whole terrain from high above one corner, and a
/// close-up a few tens of metres above the ground in the middle of the map.
std::vector<BenchView> benchViews(const terrain::Terrain& ground) {
    const glm::vec2 size = ground.field().worldSize();
    const float top = ground.bounds().minMax(ground.bounds().levelCount() - 1, 0, 0).second;
    const glm::vec2 centre = size * 0.5f;
    const glm::vec3 far(size.x * 0.06f, top + 900.0f, size.y * 0.06f);
    const glm::vec3 close(centre.x, ground.heightAt(centre.x, centre.y) + 40.0f, centre.y);
    return {{"far", lookFrom(far, centre, -22.0f)}, {"close", lookFrom(close, size * 0.75f, -12.0f)}};
}

Result<std::vector<std::string>> deviceSelectors(const Options& options) {
    if (!options.device.empty()) return std::vector<std::string>{options.device};
    gpu::InstanceOptions io;
    io.validation = options.validation;
    auto instance = gpu::Instance::create(io);
    if (!instance) return instance.error();
    std::vector<std::string> selectors;
    for (const auto& d : instance.value()->devices()) selectors.push_back(std::to_string(d.index));
    return selectors;
}

/// The options of each row of one backend: every mode it draws, adaptive once per metric
/// (or only --tess-metric's), each metric at its default target unless
/// --tess-target was given.
std::vector<Options> benchRuns(const Options& options, const backend::BackendCapabilities& caps) {
    std::vector<Options> runs;
    for (auto mode : {terrain::TerrainMode::LowRes, terrain::TerrainMode::Continuous, terrain::TerrainMode::Adaptive}) {
        if (!caps.drawsTerrainMode(mode)) continue;
        std::vector<terrain::TessMetric> metrics = {options.tessellation.metric};
        if (mode == terrain::TerrainMode::Adaptive && !options.tessMetricGiven)
            metrics = {terrain::TessMetric::ScreenEdge, terrain::TessMetric::HeightDetail,
                       terrain::TessMetric::Distance, terrain::TessMetric::Silhouette};
        for (auto metric : metrics) {
            Options run = options;
            run.terrainMode = mode;
            run.tessellation.metric = metric;
            if (!options.tessTargetGiven) run.tessellation.targetPixels = terrain::defaultTargetPixels(metric);
            runs.push_back(std::move(run));
        }
    }
    return runs;
}

/// The benchmark summary of frames [first, end) of `source`. The GPU passes
/// are summarised by profiler::summarize() over a copy holding only those
/// frames; CPU frames cannot be copied into another profiler (it times them
/// itself), so their series is summarised here with the same definitions
/// (median of an even count: the mean of the middle two).
profiler::BenchmarkSummary summarizeFrames(const profiler::Profiler& source, uint64_t first, uint64_t end) {
    profiler::Profiler rows;
    rows.setEnabled(true);
    for (const auto& pass : source.gpuPasses())
        if (pass.frame >= first && pass.frame < end) rows.recordGpuPass(pass);
    profiler::BenchmarkSummary summary = profiler::summarize(rows);
    std::vector<uint64_t> ns;
    for (const auto& frame : source.frameEvents())
        if (frame.frame >= first && frame.frame < end) ns.push_back(frame.durationNs);
    std::sort(ns.begin(), ns.end());
    profiler::PassSummary& cpu = summary.cpuFrame;
    cpu = {};
    cpu.name = "cpu frame";
    cpu.samples = ns.size();
    if (!ns.empty()) {
        const size_t n = ns.size();
        cpu.minMs = double(ns.front()) / 1e6;
        cpu.maxMs = double(ns.back()) / 1e6;
        cpu.medianMs = double(ns[(n - 1) / 2] + ns[n / 2]) / 2e6;
        uint64_t total = 0;
        for (uint64_t v : ns) total += v;
        cpu.meanMs = double(total) / 1e6 / double(n);
    }
    summary.frames = std::max<size_t>(summary.frames, ns.size());
    return summary;
}

TerrainBenchRecord makeRecord(const RenderSession& session, const char* view,
                              const terrain::TessellationSettings& settings, const profiler::BenchmarkSummary& summary) {
    TerrainBenchRecord r;
    r.backend = session.capabilities().name;
    r.mode = terrain::toString(settings.mode);
    r.view = view;
    r.device = session.deviceName();
    r.driver = session.driverName();
    r.width = session.width();
    r.height = session.height();
    if (summary.gpuFrame.statsMedianFrame) r.triangles = profiler::trianglesOf(*summary.gpuFrame.statsMedianFrame);
    r.patches = session.lastPatchCount();
    r.gpuMsMedian = summary.gpuFrame.medianMs;
    r.gpuMsMin = summary.gpuFrame.minMs;
    r.gpuMsMax = summary.gpuFrame.maxMs;
    r.cpuFrameMsMedian = summary.cpuFrame.medianMs;
    r.frames = static_cast<uint32_t>(summary.gpuFrame.samples);
    const bool adaptive = settings.mode == terrain::TerrainMode::Adaptive;
    r.metric = adaptive ? terrain::toString(settings.metric) : "-";
    r.targetPixels = adaptive ? settings.targetPixels : 0.0;
    r.continuousLevel = settings.mode == terrain::TerrainMode::Continuous ? settings.continuousLevel : 0.0;
    r.tessMax = adaptive ? settings.maxLevel : 0.0;
    if (const auto& stats = summary.gpuFrame.statsMedianFrame) {
        r.vertexShaderInvocations = stats->vertexShaderInvocations;
        r.tessEvaluationInvocations = stats->tessEvaluationInvocations;
        r.geometryShaderInvocations = stats->geometryShaderInvocations;
    }
    const std::string terrainPass = std::string("terrain.") + terrain::toString(settings.mode);
    for (const profiler::PassSummary& pass : summary.passes) {
        TerrainBenchPass p;
        p.name = pass.name;
        p.gpuMsMedian = pass.medianMs;
        if (pass.statsMedianFrame) {
            p.clippingInvocations = pass.statsMedianFrame->clippingInvocations;
            p.vertexShaderInvocations = pass.statsMedianFrame->vertexShaderInvocations;
            p.tessEvaluationInvocations = pass.statsMedianFrame->tessEvaluationInvocations;
            p.geometryShaderInvocations = pass.statsMedianFrame->geometryShaderInvocations;
        }
        if (p.name == terrainPass) r.clippingInvocations = p.clippingInvocations;
        r.passes.push_back(std::move(p));
    }
    r.intermediateBytes = session.lastFrameReport().intermediateBytes;
    return r;
}

/// The emulated tessellator's largest level: the common cap of --backend all.
constexpr float kComparisonMaxLevel = tessellator::ContinuousLevel::kMaxLevel;

} // namespace

Status runTerrainBenchmark(const Options& options) {
    auto& profiler = profiler::Profiler::global();
    profiler.setEnabled(true);
    auto loaded = World::load(options, 1);
    if (!loaded) return loaded.error();
    terrain::Terrain& ground = loaded.value()->terrain();
    auto devices = deviceSelectors(options);
    if (!devices) return devices.error();
    const bool compare = options.backend == "all";
    std::vector<std::string> backends;
    if (compare) backends = {kComparisonReference, "r2vb", "streamout"};
    else if (!options.backend.empty()) backends.push_back(options.backend);
    else backends.assign(std::begin(kBackendPreference), std::end(kBackendPreference));
    const uint32_t warmup = options.warmup ? options.warmup : 3;
    const uint32_t frames = options.frames ? options.frames : 10;
    auto level = [](float value) {
        std::ostringstream text;
        text << value;
        return text.str();
    };
    if (compare && options.tessMaxGiven && options.tessellation.maxLevel > kComparisonMaxLevel)
        return fail("--tess-max ", level(options.tessellation.maxLevel),
                    ": --backend all compares the backends at the emulated tessellator's levels, 1 to ",
                    level(kComparisonMaxLevel));
    const std::filesystem::path traceDir = benchTraceDirectory(options);
    if (!traceDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(traceDir, ec);
        if (ec) return fail("--out-dir ", traceDir.string(), ": ", ec.message());
    }

    // --look both: each row twice, plain then full, on the same session.
    std::vector<backend::Look> looks = {options.look};
    if (options.benchBothLooks) looks = {backend::Look::Plain, backend::Look::Full};
    std::vector<TerrainBenchRecord> records;
    std::vector<std::string> notes;
    if (compare && options.tessellation.continuousLevel > kComparisonMaxLevel)
        notes.push_back("continuous level " + level(options.tessellation.continuousLevel) + " runs as " +
                        level(kComparisonMaxLevel) + " on every backend, the emulated tessellator's maximum");
    uint32_t frameIndex = 0;
    for (const auto& device : devices.value()) {
        for (const auto& backendName : backends) {
            Options run = options;
            run.device = device;
            run.backend = backendName;
            profiler.clear();
            auto created = RenderSession::create(run, ground);
            if (!created) {
                log::warning("skipping " + backendName + " on device " + device + ": " + created.error().message);
                notes.push_back(backendName + " skipped on device " + device + ": " + created.error().message);
                continue;
            }
            RenderSession& session = *created.value();
            const auto& caps = session.capabilities();
            if (compare) {
                // One cap for every backend, so all draw the same triangles.
                if (!options.tessMaxGiven) run.tessellation.maxLevel = kComparisonMaxLevel;
                run.tessellation.continuousLevel = std::min(run.tessellation.continuousLevel, kComparisonMaxLevel);
            }
            run.tessellation.continuousLevel = std::min(run.tessellation.continuousLevel, caps.maxTessFactor);
            run.tessMaxGiven = false; // levels above the backend's maximum clamp to it
            std::vector<std::string> missing;
            for (auto mode : {terrain::TerrainMode::Continuous, terrain::TerrainMode::Adaptive})
                if (!caps.drawsTerrainMode(mode)) missing.push_back(terrain::toString(mode));
            if (!missing.empty()) {
                std::string modes;
                for (const auto& m : missing) modes += (modes.empty() ? "" : ", ") + m;
                notes.push_back(caps.name + " on " + session.deviceName() + " does not draw " + modes);
            }
            const std::string tracePath =
                traceDir.empty()
                    ? std::string()
                    : (traceDir / ("bench-" + caps.name +
                                   (devices.value().size() > 1 ? "-device" + device : std::string()) + ".json"))
                          .string();
            const size_t firstRecord = records.size();
            for (const BenchView& view : benchViews(ground)) {
                scene::Camera camera;
                camera.setPose(view.pose);
                camera.setAspect(float(session.width()) / float(session.height()));
                for (const Options& row : benchRuns(run, caps)) {
                    auto settings = session.resolveTessellation(row);
                    if (!settings) return settings.error();
                    for (const backend::Look look : looks) {
                        session.setLook(look);
                        const uint32_t first = frameIndex;
                        const uint64_t rowStartNs = profiler.nowNs();
                        for (uint32_t f = 0; f < warmup + frames; ++f, ++frameIndex) {
                            profiler.beginFrame(frameIndex);
                            session.renderFrame(frameIndex, camera, settings.value(), options.clearColor, false, false);
                            profiler.endFrame();
                            profiler.recordCounter({"intermediate bytes", frameIndex, profiler.nowNs(),
                                                    double(session.lastFrameReport().intermediateBytes)});
                        }
                        session.finish();
                        records.push_back(makeRecord(session, view.name, settings.value(),
                                                     summarizeFrames(profiler, first + warmup, frameIndex)));
                        TerrainBenchRecord& r = records.back();
                        r.look = look == backend::Look::Plain ? "plain" : "full";
                        r.trace = tracePath;
                        // One slice per row on the CPU track, so the trace reads
                        // as the table's rows.
                        const std::string label = std::string(view.name) + " " + r.mode +
                                                  (r.metric != "-" ? "/" + r.metric : std::string()) +
                                                  (looks.size() > 1 ? " " + r.look : std::string());
                        profiler.recordCpu({internBenchName(label), profiler::Profiler::currentThreadId(), first, rowStartNs,
                                            profiler.nowNs() - rowStartNs, 0});
                        log::info(r.device + " " + r.backend + " " + r.view + " " + r.mode + " " + r.metric + ": " +
                                  std::to_string(r.gpuMsMedian) + " ms, " + std::to_string(r.triangles) + " triangles" +
                                  (looks.size() > 1 ? ", look " + r.look : std::string()));
                    }
                }
            }
            if (!tracePath.empty() && records.size() > firstRecord) {
                if (auto w = writeBenchTrace(profiler, tracePath, "tessera bench terrain", session); !w) return w;
            }
        }
    }
    profiler.clear();
    if (records.empty()) return fail("--bench terrain: no backend could run on any device");
    const std::string json = terrainBenchJson(records);
    std::string table = terrainBenchTable(records);
    if (compare) table += backendComparisonTable(records, notes);
    return writeBenchOutputs(options, json, table);
}

} // namespace tessera::runtime
