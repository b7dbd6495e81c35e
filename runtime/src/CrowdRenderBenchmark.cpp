#include "CrowdRenderBenchmark.h"

#include "tessera/runtime/BackendSelection.h"
#include "BenchOutputs.h"
#include "CrowdRenderBenchReport.h"
#include "tessera/runtime/SceneRun.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/scene/CameraPose.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace tessera::runtime {
namespace {

constexpr uint32_t kDefaultSizes[] = {1000, 10000, 65000};
constexpr uint32_t kDefaultWarmup = 10;
constexpr uint32_t kDefaultFrames = 30;
constexpr const char* kTierPasses[3] = {"crowd.near", "crowd.middle", "crowd.far"};
constexpr const char* kTierCounters[3] = {"crowd near instances", "crowd middle instances", "crowd far instances"};

/// Per frame in [first, end), the summed durations of the CPU scopes named `name`.
std::vector<double> cpuScope(const profiler::Profiler& profiler, const char* name, uint64_t first, uint64_t end) {
    std::map<uint64_t, double> perFrame;
    for (uint64_t f = first; f < end; ++f) perFrame[f] = 0.0;
    for (const auto& e : profiler.cpuEvents())
        if (e.frame >= first && e.frame < end && std::string_view(e.name) == name)
            perFrame[e.frame] += double(e.durationNs) / 1e6;
    std::vector<double> out;
    for (const auto& [f, ms] : perFrame) out.push_back(ms);
    return out;
}

/// Lavapipe's timestamps can miss a pass's rasterisation: a pass that draws
/// a large share of the frame's triangles in a tiny share of its GPU time
/// is named rather than trusted.
std::vector<std::string> suspectPasses(const std::map<std::string, std::pair<double, double>>& msAndTriangles,
                                       double gpuFrameMs) {
    double triangles = 0.0;
    for (const auto& [name, v] : msAndTriangles) triangles += v.second;
    std::vector<std::string> out;
    if (triangles <= 0.0 || gpuFrameMs <= 0.0) return out;
    for (const auto& [name, v] : msAndTriangles) {
        const double triangleShare = v.second / triangles;
        const double timeShare = v.first / gpuFrameMs;
        if (triangleShare > 0.1 && timeShare < 0.1 * triangleShare) out.push_back(name);
    }
    return out;
}

void summarize(const profiler::Profiler& profiler, uint64_t first, uint64_t end, bool cpuDevice, CrowdRenderRow& row) {
    std::map<uint64_t, double> gpuFrame;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> ms, triangles;
    for (const auto& pass : profiler.gpuPasses()) {
        if (pass.frame < first || pass.frame >= end) continue;
        const double d = double(pass.durationNs) / 1e6;
        gpuFrame[pass.frame] += d;
        if (!ms.count(pass.name)) order.push_back(pass.name);
        ms[pass.name].push_back(d);
        if (pass.stats) triangles[pass.name].push_back(double(pass.stats->clippingInvocations));
    }
    std::vector<double> frames;
    for (const auto& [f, d] : gpuFrame) frames.push_back(d);
    row.gpuFrame = summarizeSeries(frames);
    double crowdMs = 0.0;
    std::map<std::string, std::pair<double, double>> draws;
    for (const std::string& name : order) {
        const double median = summarizeSeries(ms[name]).median;
        row.passes.emplace_back(name, median);
        const double tri = summarizeSeries(triangles[name]).median;
        if (tri > 0.0) draws[name] = {median, tri};
        if (name.rfind("crowd.", 0) != 0) continue;
        crowdMs += median;
        bool tier = false;
        for (int t = 0; t < 3; ++t)
            if (name == kTierPasses[t]) {
                row.tierMs[size_t(t)] = median;
                row.tierTriangles[size_t(t)] = tri;
                tier = true;
            }
        if (tier) continue;
        if (name == "crowd.skin")
            row.skinMs += median;
        else
            row.cullBinMs += median;
    }
    row.terrainMs = std::max(0.0, row.gpuFrame.median - crowdMs);
    if (cpuDevice) row.suspectPasses = suspectPasses(draws, row.gpuFrame.median);

    std::vector<double> cpu;
    for (const auto& f : profiler.frameEvents())
        if (f.frame >= first && f.frame < end) cpu.push_back(double(f.durationNs) / 1e6);
    row.cpuFrame = summarizeSeries(cpu);
    row.simulation = summarizeSeries(cpuScope(profiler, "crowd.step", first, end));
    row.lod = summarizeSeries(cpuScope(profiler, "crowd.lod", first, end));
    row.instances = summarizeSeries(cpuScope(profiler, "crowd.draw", first, end));
    std::map<std::string, std::vector<double>> counters;
    for (const auto& c : profiler.counters())
        if (c.frame >= first && c.frame < end) counters[c.name].push_back(c.value);
    for (int t = 0; t < 3; ++t) row.tierInstances[size_t(t)] = summarizeSeries(counters[kTierCounters[t]]).median;
    row.frames = uint32_t(end - first);
}

std::vector<std::string> backendsFor(const Options& options) {
    if (options.backend == "all") return {"hulldomain", "r2vb", "streamout"};
    return {options.backend}; // empty: RenderSession picks the device's best
}

} // namespace

Status runCrowdRenderBenchmark(const Options& options) {
    auto& profiler = profiler::Profiler::global();
    profiler.setEnabled(true);
    const bool compare = options.backend == "all";
    const std::vector<uint32_t> sizes = options.agents.empty()
                                            ? std::vector<uint32_t>(std::begin(kDefaultSizes), std::end(kDefaultSizes))
                                            : options.agents;

    CrowdRenderSummary summary;
    summary.width = options.sizeGiven ? options.width : 1920;
    summary.height = options.sizeGiven ? options.height : 1080;
    summary.warmupFrames = options.warmupGiven ? options.warmup : kDefaultWarmup;
    summary.frames = options.frames ? options.frames : kDefaultFrames;
    summary.meteors = options.meteors;
    summary.terrain = options.heightmap.empty() ? "content/terrain/height.png" : options.heightmap;
    const uint32_t total = summary.warmupFrames + summary.frames;

    const std::filesystem::path traceDir = benchTraceDirectory(options);
    if (!traceDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(traceDir, ec);
        if (ec) return fail("--out-dir ", traceDir.string(), ": ", ec.message());
    }

    // Each size is seen across its own crowd (unless --camera); the terrain
    // alone runs after the first size, from its camera.
    std::optional<scene::CameraPose> pose = options.camera, firstPose;
    std::vector<uint32_t> order;
    for (size_t i = 0; i < sizes.size(); ++i) {
        order.push_back(sizes[i]);
        if (i == 0) order.push_back(0);
    }
    std::set<std::string> skipped;
    for (const uint32_t agents : order) {
        pose = options.camera ? options.camera : (agents ? std::nullopt : firstPose);
        for (const std::string& backendName : backendsFor(options)) {
            if (skipped.count(backendName)) continue;
            Options run = options;
            run.backend = backendName;
            run.width = summary.width;
            run.height = summary.height;
            run.scene = agents ? "crowd" : "terrain";
            run.agents = agents ? std::vector<uint32_t>{agents} : std::vector<uint32_t>{};
            run.camera = pose;
            run.meteors = agents ? options.meteors : 0;
            profiler.clear();
            auto created = SceneRun::create(run, total);
            if (!created) {
                if (!compare) return created.error();
                log::warning("skipping " + backendName + ": " + created.error().message);
                summary.notes.push_back(backendName + " skipped: " + created.error().message);
                skipped.insert(backendName);
                continue;
            }
            SceneRun& scene = *created.value();
            RenderSession& session = scene.session();
            if (!pose && scene.world().simulatedCrowd()) {
                pose = scene.world().simulatedCrowd()->acrossPose();
                scene.world().fixCamera(*pose);
                if (!firstPose) firstPose = pose;
            }
            if (agents && !scene.instancedCrowd())
                summary.notes.push_back(session.capabilities().name + " at " + std::to_string(agents) +
                                        " agents: no instanced crowd on this backend (drawn with the character path)");
            for (uint32_t f = 0; f < total; ++f) {
                profiler.beginFrame(f);
                scene.renderFrame(f, false);
                profiler.endFrame();
            }
            session.finish();
            CrowdRenderRow& row = summary.rows.emplace_back();
            row.backend = session.capabilities().name;
            row.device = session.deviceName();
            row.driver = session.driverName();
            row.agents = agents;
            row.crowdBytes = session.lastFrameReport().crowdBytes;
            row.camera = scene::formatCameraPose(scene.camera().pose());
            summarize(profiler, summary.warmupFrames, total, session.deviceClass() == lod::DeviceClass::Cpu, row);
            const std::string rowName =
                "bench-crowd-" + row.backend + "-" + (agents ? std::to_string(agents) : std::string("terrain"));
            if (!traceDir.empty()) {
                row.trace = (traceDir / (rowName + ".json")).string();
                if (auto w = writeBenchTrace(profiler, row.trace, "tessera bench crowd", session); !w) return w;
            }
            log::info(row.backend + " " + (agents ? std::to_string(agents) + " agents" : std::string("terrain alone")) +
                      ": GPU " + formatNumber(row.gpuFrame.median) + " ms, CPU " + formatNumber(row.cpuFrame.median) +
                      " ms");
        }
    }
    profiler.clear();
    if (summary.rows.empty()) return fail("--bench crowd: no backend could run");
    summary.camera = options.camera
                         ? scene::formatCameraPose(*options.camera)
                         : "across each crowd (SimulatedCrowd::acrossPose); the terrain alone from the first's";
    std::stable_sort(summary.rows.begin(), summary.rows.end(),
                     [](const CrowdRenderRow& a, const CrowdRenderRow& b) { return a.agents < b.agents; });
    return writeBenchOutputs(options, crowdRenderBenchJson(summary), crowdRenderBenchTable(summary));
}

} // namespace tessera::runtime
