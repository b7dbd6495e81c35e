#include "TerrainBenchmark.h"

#include "BackendSelection.h"
#include "DemoScene.h"
#include "RenderSession.h"
#include "TerrainBenchReport.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/Instance.h"
#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/Profiler.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace tessera::demo {

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

Result<std::vector<std::string>> deviceSelectors(const DemoOptions& options) {
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
std::vector<DemoOptions> benchRuns(const DemoOptions& options, const backend::BackendCapabilities& caps) {
    std::vector<DemoOptions> runs;
    for (auto mode : {terrain::TerrainMode::LowRes, terrain::TerrainMode::Continuous, terrain::TerrainMode::Adaptive}) {
        if (!caps.drawsTerrainMode(mode)) continue;
        std::vector<terrain::TessMetric> metrics = {options.tessellation.metric};
        if (mode == terrain::TerrainMode::Adaptive && !options.tessMetricGiven)
            metrics = {terrain::TessMetric::ScreenEdge, terrain::TessMetric::HeightDetail,
                       terrain::TessMetric::Distance, terrain::TessMetric::Silhouette};
        for (auto metric : metrics) {
            DemoOptions run = options;
            run.terrainMode = mode;
            run.tessellation.metric = metric;
            if (!options.tessTargetGiven) run.tessellation.targetPixels = terrain::defaultTargetPixels(metric);
            runs.push_back(std::move(run));
        }
    }
    return runs;
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
    return r;
}

} // namespace

Status runTerrainBenchmark(const DemoOptions& options) {
    auto& profiler = profiler::Profiler::global();
    profiler.setEnabled(true);
    auto loaded = DemoScene::load(options, 1);
    if (!loaded) return loaded.error();
    terrain::Terrain& ground = loaded.value()->terrain();
    auto devices = deviceSelectors(options);
    if (!devices) return devices.error();
    std::vector<std::string> backends;
    if (!options.backend.empty()) backends.push_back(options.backend);
    else backends.assign(std::begin(kBackendPreference), std::end(kBackendPreference));
    const uint32_t warmup = options.warmup ? options.warmup : 3;
    const uint32_t frames = options.frames ? options.frames : 10;

    std::vector<TerrainBenchRecord> records;
    uint32_t frameIndex = 0;
    for (const auto& device : devices.value()) {
        for (const auto& backendName : backends) {
            DemoOptions run = options;
            run.device = device;
            run.backend = backendName;
            auto created = RenderSession::create(run, ground);
            if (!created) {
                log::warning("skipping " + backendName + " on device " + device + ": " + created.error().message);
                continue;
            }
            RenderSession& session = *created.value();
            const auto& caps = session.capabilities();
            run.tessellation.continuousLevel = std::min(run.tessellation.continuousLevel, caps.maxTessFactor);
            run.tessMaxGiven = false;
            for (const BenchView& view : benchViews(ground)) {
                scene::Camera camera;
                camera.setPose(view.pose);
                camera.setAspect(float(session.width()) / float(session.height()));
                for (const DemoOptions& row : benchRuns(run, caps)) {
                    auto settings = session.resolveTessellation(row);
                    if (!settings) return settings.error();
                    profiler.clear();
                    const uint32_t first = frameIndex;
                    for (uint32_t f = 0; f < warmup + frames; ++f, ++frameIndex) {
                        profiler.beginFrame(frameIndex);
                        session.renderFrame(frameIndex, camera, settings.value(), options.clearColor, false, false);
                        profiler.endFrame();
                    }
                    session.finish();
                    profiler.discardFramesBefore(first + warmup);
                    records.push_back(makeRecord(session, view.name, settings.value(), profiler::summarize(profiler)));
                    const TerrainBenchRecord& r = records.back();
                    log::info(r.device + " " + r.backend + " " + r.view + " " + r.mode + " " + r.metric + ": " +
                              std::to_string(r.gpuMsMedian) + " ms, " + std::to_string(r.triangles) + " triangles");
                }
            }
        }
    }
    if (records.empty()) return fail("--bench terrain: no backend could run on any device");
    const std::string json = terrainBenchJson(records);
    const std::string table = terrainBenchTable(records);
    if (options.benchOut.empty()) {
        std::fputs(json.c_str(), stdout);
        std::fputs(table.c_str(), stderr);
        return {};
    }
    std::ofstream out(options.benchOut, std::ios::binary | std::ios::trunc);
    if (!(out << json) || !out.flush()) return fail("--out ", options.benchOut, ": cannot write the file");
    std::fputs(table.c_str(), stdout);
    log::info("wrote " + options.benchOut);
    return {};
}

} // namespace tessera::demo
