#include "bench/CrowdRenderBenchmark.h"

#include "bench/BenchDriver.h"
#include "bench/CrowdRenderBenchReport.h"
#include "bench/PassTimes.h"
#include "tessera/runtime/InstancedCrowd.h"
#include "tessera/runtime/SceneRun.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/scene/CameraPose.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

namespace tessera::runtime {
namespace {

constexpr uint32_t kDefaultSizes[] = {1000, 10000, 65000};
constexpr const char* kTierPasses[lod::kTierCount] = {"crowd.near", "crowd.middle", "crowd.far", "crowd.impostor"};
constexpr const char* kTierCounters[lod::kTierCount] = {"crowd near instances", "crowd middle instances",
                                                       "crowd far instances", "crowd impostor instances"};

BenchPlan crowdPlan() {
    BenchPlan plan;
    plan.name = "crowd";
    plan.setting = setting::kCrowdBenchmark;
    plan.comparison = {"hulldomain", "r2vb", "streamout", "meshshader"};
    plan.everyPreferred = false;
    plan.warmup = 10;
    plan.frames = 30;
    plan.alwaysWarmUp = false;
    plan.width = 1920;
    plan.height = 1080;
    return plan;
}

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

/// Lavapipe's timestamps can miss a pass's rasterisation, which a later
/// pass's then carry: a pass that draws a large share of the frame's
/// triangles in a tiny share of its GPU time, or one that draws next to
/// nothing in a large share of it (measured: an empty far tier read 30 to
/// 50 ms of an 80 ms frame, 2026-11-29), is named rather than trusted.
std::vector<std::string> suspectPasses(const std::map<std::string, std::pair<double, double>>& msAndTriangles,
                                       double gpuFrameMs) {
    double triangles = 0.0;
    for (const auto& [name, v] : msAndTriangles) triangles += v.second;
    std::vector<std::string> out;
    if (triangles <= 0.0 || gpuFrameMs <= 0.0) return out;
    for (const auto& [name, v] : msAndTriangles) {
        const double triangleShare = v.second / triangles;
        const double timeShare = v.first / gpuFrameMs;
        if ((triangleShare > 0.1 && timeShare < 0.1 * triangleShare) || (triangleShare < 0.01 && timeShare > 0.2))
            out.push_back(name);
    }
    return out;
}

/// The row's GPU figures from the passes of frames [first, end): per pass,
/// the crowd's passes grouped (culling and binning, skinning, each tier),
/// the rest as the terrain's.
void summarizeGpu(const profiler::Profiler& profiler, uint64_t first, uint64_t end, bool cpuDevice,
                  CrowdRenderRow& row) {
    PassTimes times;
    std::map<std::string, std::vector<double>> triangles;
    for (const auto& pass : profiler.gpuPasses()) {
        if (pass.frame < first || pass.frame >= end) continue;
        times.add(pass, false, true);
        if (pass.stats) triangles[pass.name].push_back(double(profiler::generatedPrimitivesOf(*pass.stats)));
    }
    row.gpuFrame = summarizeSeries(times.frameTotals());
    row.passes = times.passMedians();
    double crowdMs = 0.0;
    std::map<std::string, std::pair<double, double>> draws;
    for (const auto& [name, median] : row.passes) {
        const double tri = summarizeSeries(triangles[name]).median;
        // The tiers' passes even when they drew nothing: they are charted.
        if (tri > 0.0 || std::find(std::begin(kTierPasses), std::end(kTierPasses), name) != std::end(kTierPasses))
            draws[name] = {median, tri};
        if (name.rfind("crowd.", 0) != 0) continue;
        crowdMs += median;
        const auto tier = std::find(std::begin(kTierPasses), std::end(kTierPasses), name);
        if (tier != std::end(kTierPasses)) {
            row.tierMs[size_t(tier - std::begin(kTierPasses))] = median;
            row.tierTriangles[size_t(tier - std::begin(kTierPasses))] = tri;
        } else if (name == "crowd.skin") {
            row.skinMs += median;
        } else {
            row.cullBinMs += median;
        }
    }
    row.terrainMs = std::max(0.0, row.gpuFrame.median - crowdMs);
    if (cpuDevice) row.suspectPasses = suspectPasses(draws, row.gpuFrame.median);
}

/// The row's CPU figures of frames [first, end): the frame, the crowd's
/// simulation, LOD and instances, and the tiers' instances the GPU drew.
void summarizeCpu(const profiler::Profiler& profiler, uint64_t first, uint64_t end, CrowdRenderRow& row) {
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
    for (uint32_t t = 0; t < lod::kTierCount; ++t)
        row.tierInstances[size_t(t)] = summarizeSeries(counters[kTierCounters[t]]).median;
    row.frames = uint32_t(end - first);
}

/// --bench crowd: each crowd size on each backend, the terrain alone
/// after the first size.
class CrowdRenderBench {
public:
    explicit CrowdRenderBench(const BenchDriver& driver) : mDriver(driver) {
        const Options& options = driver.options();
        mSummary.width = driver.width();
        mSummary.height = driver.height();
        mSummary.warmupFrames = driver.warmup();
        mSummary.frames = driver.frames();
        mSummary.meteors = options.meteors;
        mSummary.terrain = options.heightmap.empty() ? "content/terrain/height.png" : options.heightmap;
    }

    /// The crowd of `agents` (0: the terrain alone) on every backend not
    /// skipped yet; an error ends the benchmark.
    Status runSize(uint32_t agents);
    /// The rows in crowd-size order, then the outputs.
    Status finish();

private:
    /// The crowd scene of `agents` (the terrain scene for 0) on `backend`,
    /// from the size's camera.
    Options rowOptions(const std::string& backend, uint32_t agents) const;
    /// One row: warm-up and measured frames, their figures and trace.
    Status measureRow(SceneRun& scene, uint32_t agents);

    const BenchDriver& mDriver;
    CrowdRenderSummary mSummary;
    /// Each size is seen across its own crowd (unless the options fix the
    /// camera); the terrain alone from the first size's camera.
    std::optional<scene::CameraPose> mPose, mFirstPose;
    std::set<std::string> mSkipped;
};

Options CrowdRenderBench::rowOptions(const std::string& backend, uint32_t agents) const {
    Options run = mDriver.runOptions(backend);
    run.scene = agents ? "crowd" : "terrain";
    run.agents = agents ? std::vector<uint32_t>{agents} : std::vector<uint32_t>{};
    run.camera = mPose;
    run.meteors = agents ? mDriver.options().meteors : 0;
    return run;
}

Status CrowdRenderBench::runSize(uint32_t agents) {
    const Options& options = mDriver.options();
    mPose = options.camera ? options.camera : (agents ? std::nullopt : mFirstPose);
    for (const std::string& backend : mDriver.backends()) {
        if (mSkipped.count(backend)) continue;
        profiler::Profiler::global().clear();
        auto created = SceneRun::create(rowOptions(backend, agents), mSummary.warmupFrames + mSummary.frames);
        if (!created) {
            if (Status skipped = mDriver.skip(backend, created.error(), mSummary.notes); !skipped) return skipped;
            mSkipped.insert(backend);
            continue;
        }
        SceneRun& scene = *created.value();
        if (!mPose && scene.world().simulatedCrowd()) {
            mPose = scene.world().simulatedCrowd()->acrossPose();
            scene.world().fixCamera(*mPose);
            if (!mFirstPose) mFirstPose = mPose;
        }
        if (Status ok = measureRow(scene, agents); !ok) return ok;
    }
    return {};
}

Status CrowdRenderBench::measureRow(SceneRun& scene, uint32_t agents) {
    RenderSession& session = scene.session();
    if (agents && !scene.instancedCrowd())
        mSummary.notes.push_back(session.capabilities().name + " at " + std::to_string(agents) +
                                 " agents: no instanced crowd on this backend (drawn with the character path)");
    const uint32_t total = mDriver.renderFrames(0, mSummary.warmupFrames + mSummary.frames,
                                                [&scene](uint32_t frame) { scene.renderFrame(frame, false); });
    session.finish();
    CrowdRenderRow& row = mSummary.rows.emplace_back();
    row.backend = session.capabilities().name;
    row.device = session.deviceName();
    row.driver = session.driverName();
    row.agents = agents;
    row.crowdBytes = session.lastFrameReport().crowdBytes;
    row.camera = scene::formatCameraPose(scene.camera().pose());
    const auto& profiler = profiler::Profiler::global();
    summarizeGpu(profiler, mSummary.warmupFrames, total, session.deviceClass() == lod::DeviceClass::Cpu, row);
    summarizeCpu(profiler, mSummary.warmupFrames, total, row);
    // The agents the terrain hides, by tier, counted once on the last frame
    // (untimed): the frames themselves test only the agents a budget counts
    // (LodManager::testEveryHorizon), the backends cull the impostors.
    if (const InstancedCrowd* crowd = scene.instancedCrowd()) {
        const std::array<uint32_t, lod::kTierCount> hidden = crowd->countHidden();
        for (uint32_t t = 0; t < lod::kTierCount; ++t) row.tierHidden[t] = hidden[t];
    }
    row.trace = mDriver.tracePath("crowd-" + row.backend + "-" +
                                  (agents ? std::to_string(agents) : std::string("terrain")));
    if (Status written = mDriver.writeTrace(row.trace, session); !written) return written;
    log::info(row.backend + " " + (agents ? std::to_string(agents) + " agents" : std::string("terrain alone")) +
              ": GPU " + formatNumber(row.gpuFrame.median) + " ms, CPU " + formatNumber(row.cpuFrame.median) + " ms");
    return {};
}

Status CrowdRenderBench::finish() {
    const Options& options = mDriver.options();
    mSummary.camera = options.camera
                          ? scene::formatCameraPose(*options.camera)
                          : "across each crowd (SimulatedCrowd::acrossPose); the terrain alone from the first's";
    std::stable_sort(mSummary.rows.begin(), mSummary.rows.end(),
                     [](const CrowdRenderRow& a, const CrowdRenderRow& b) { return a.agents < b.agents; });
    return mDriver.finish(mSummary.rows.size(), crowdRenderBenchJson(mSummary), crowdRenderBenchTable(mSummary));
}

} // namespace

Status runCrowdRenderBenchmark(const Options& options) {
    auto driver = BenchDriver::start(options, crowdPlan());
    if (!driver) return driver.error();
    const std::vector<uint32_t> sizes = options.agents.empty()
                                            ? std::vector<uint32_t>(std::begin(kDefaultSizes), std::end(kDefaultSizes))
                                            : options.agents;
    CrowdRenderBench bench(driver.value());
    for (size_t i = 0; i < sizes.size(); ++i) {
        if (Status ok = bench.runSize(sizes[i]); !ok) return ok;
        if (i == 0)
            if (Status ok = bench.runSize(0); !ok) return ok;
    }
    return bench.finish();
}

} // namespace tessera::runtime
