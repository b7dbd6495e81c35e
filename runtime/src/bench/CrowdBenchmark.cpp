#include "bench/CrowdBenchmark.h"

#include "bench/BenchDriver.h"
#include "bench/CrowdBenchReport.h"
#include "crowd/CrowdSetup.h"
#include "tessera/runtime/World.h"
#include "crowd/SystemInfo.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/core/ParallelFor.h"
#include "tessera/terrain/MeteorShower.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace tessera::runtime {
namespace {

constexpr uint32_t kDefaultSizes[] = {1000, 10000, 65000};
constexpr uint32_t kDefaultSteps = 300;
/// measureOverlap() looks at every pair within reach, so it runs on every
/// this many measured steps (untimed), and after the last.
constexpr uint32_t kOverlapEvery = 30;

/// Per measured step, ms.
struct StepTimes {
    std::vector<double> total, fields, avoidance, integration, wall;
};

void worstOf(crowd::OverlapReport& worst, const crowd::OverlapReport& sample) {
    worst.pairs = std::max(worst.pairs, sample.pairs);
    worst.worst = std::max(worst.worst, sample.worst);
    worst.overlapping = std::max(worst.overlapping, sample.overlapping);
}

/// Craters one every kMeteorIntervalSeconds over `seconds`, anywhere on the spawn disc.
std::vector<terrain::MeteorImpact> meteors(const crowd::Region& spawn, const terrain::Terrain& ground, uint32_t seed,
                                           double seconds) {
    terrain::MeteorShowerSettings shower;
    shower.count = uint32_t(std::floor(seconds / kMeteorIntervalSeconds));
    shower.seed = seed;
    shower.durationSeconds = double(shower.count) * kMeteorIntervalSeconds;
    shower.scatter = spawn.halfSize.x;
    shower.regionMax = ground.field().worldSize();
    return terrain::scheduleMeteorShower(shower, [&spawn](double) { return spawn.center; });
}

/// One crowd size on its own copy of `field`.
Result<CrowdBenchRun> runSize(const terrain::HeightField& field, const crowd::CrowdSettings& settings,
                              const crowd::SpawnPattern& pattern, uint32_t agents, const CrowdBenchSummary& s) {
    terrain::Terrain ground(field);
    auto planned = planCrowd(ground, settings, agents, pattern);
    if (!planned) return planned.error();
    crowd::Crowd& crowd = *planned.value().crowd;
    CrowdBenchRun run;
    run.agents = agents;
    run.layout = describeLayout(planned.value().layout);
    run.createMs = planned.value().createMs;
    const uint32_t total = s.warmupSteps + s.steps;
    const auto impacts = meteors(planned.value().layout.spawn, ground, s.seed, double(total) * settings.timeStep);
    StepTimes times;
    double tilesSolved = 0.0;
    for (uint32_t step = 0; step < total; ++step) {
        while (run.impacts < impacts.size() && impacts[run.impacts].timeSeconds <= crowd.time())
            ground.splat(impacts[run.impacts++].splat);
        const auto start = std::chrono::steady_clock::now();
        crowd.step();
        const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (step < s.warmupSteps) continue;
        const crowd::CrowdTimings& t = crowd.lastTimings();
        times.total.push_back(t.total());
        times.fields.push_back(t.fields);
        times.avoidance.push_back(t.avoidance);
        times.integration.push_back(t.integration);
        times.wall.push_back(wall);
        const crowd::CrowdStats& stats = crowd.stats();
        tilesSolved += stats.fieldTilesSolved;
        run.fleeingMax = std::max(run.fleeingMax, stats.fleeing);
        run.stuckMax = std::max(run.stuckMax, stats.stuck);
        if ((step + 1 - s.warmupSteps) % kOverlapEvery == 0) {
            worstOf(run.overlapWorst, crowd.measureOverlap());
            ++run.overlapSamples;
        }
    }
    run.total = summarizeSeries(times.total);
    run.fields = summarizeSeries(times.fields);
    run.avoidance = summarizeSeries(times.avoidance);
    run.integration = summarizeSeries(times.integration);
    run.wall = summarizeSeries(times.wall);
    const crowd::CrowdMemory memory = crowd.memory();
    run.bytesPerAgent = memory.bytesPerAgent;
    run.agentBytes = memory.agentBytes;
    run.fieldBytes = memory.fieldBytes;
    run.overlapEnd = crowd.measureOverlap();
    worstOf(run.overlapWorst, run.overlapEnd);
    ++run.overlapSamples;
    const crowd::CrowdStats& stats = crowd.stats();
    run.arrivals = stats.arrivals;
    run.walkingEnd = stats.walking;
    run.stuckEnd = stats.stuck;
    run.maxStuckSeconds = stats.maxStuckSeconds;
    run.fleeingEnd = stats.fleeing;
    run.unreachableEnd = stats.unreachable;
    run.fieldTilesSolvedMean = s.steps ? tilesSolved / double(s.steps) : 0.0;
    run.fieldTilesWaitingEnd = stats.fieldTilesWaiting;
    run.simulatedSeconds = crowd.time();
    return run;
}

BenchPlan crowdSimPlan() {
    BenchPlan plan;
    plan.name = "crowd-sim";
    plan.setting = setting::kCrowdSimBenchmark;
    plan.warmup = 60;
    plan.alwaysWarmUp = false;
    plan.renders = false;
    return plan;
}

} // namespace

Status runCrowdBenchmark(const Options& options) {
    auto driver = BenchDriver::start(options, crowdSimPlan());
    if (!driver) return driver.error();
    auto field = loadDemoHeightField(options);
    if (!field) return field.error();
    crowd::CrowdSettings settings;
    settings.threads = options.threads;
    const crowd::SpawnPattern pattern{.seed = options.seed};
    const std::vector<uint32_t> sizes = options.agents.empty()
                                            ? std::vector<uint32_t>(std::begin(kDefaultSizes), std::end(kDefaultSizes))
                                            : options.agents;

    CrowdBenchSummary s;
    s.cpuModel = cpuModelName();
    s.cpuCores = onlineCpuCount();
    s.hardwareThreads = core::hardwareThreads();
    s.threads = settings.threads ? settings.threads : s.hardwareThreads;
    s.terrain = options.heightmap.empty() ? "content/terrain/height.png" : options.heightmap;
    s.terrainWidth = field.value().worldSize().x;
    s.terrainDepth = field.value().worldSize().y;
    s.cellSize = settings.cellSize;
    s.timeStep = settings.timeStep;
    s.warmupSteps = driver.value().warmup();
    s.steps = options.steps ? options.steps : kDefaultSteps;
    s.overlapEvery = kOverlapEvery;
    s.meteorIntervalSeconds = kMeteorIntervalSeconds;
    s.seed = options.seed;
    s.goalGroups = kCrowdGoalGroups;
    s.goalDistance = kCrowdGoalDistance;
    s.radiusMin = pattern.radiusMin;
    s.radiusMax = pattern.radiusMax;
    s.speedMin = pattern.speedMin;
    s.speedMax = pattern.speedMax;
    {
        // Refuse a size the machine cannot hold before spending minutes on the others.
        const terrain::Terrain ground(field.value());
        for (uint32_t agents : sizes)
            if (Status fits = checkCrowdFits(ground, settings, agents); !fits) return fits;
    }
    for (uint32_t agents : sizes) {
        auto run = runSize(field.value(), settings, pattern, agents, s);
        if (!run) return run.error();
        const CrowdBenchRun& r = s.runs.emplace_back(std::move(run.value()));
        char line[160];
        std::snprintf(line, sizeof line,
                      "crowd-sim %u agents: created in %.0f ms, a step takes %.2f ms (median), %u craters", agents,
                      r.createMs, r.total.median, r.impacts);
        log::info(line);
    }
    return driver.value().finish(s.runs.size(), crowdBenchJson(s), crowdBenchTable(s));
}

} // namespace tessera::runtime
