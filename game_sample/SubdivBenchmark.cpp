#include "SubdivBenchmark.h"

#include "BackendSelection.h"
#include "BenchOutputs.h"
#include "BenchSeries.h"
#include "SceneRun.h"
#include "SubdivBenchReport.h"
#include "TerrainBenchReport.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <algorithm>
#include <filesystem>
#include <map>

namespace tessera::demo {
namespace {

/// The level every backend shares (the emulated tessellator's largest).
constexpr float kSharedLevel = tessellator::ContinuousLevel::kMaxLevel;
/// The procedural displacement of the displaced rows.
constexpr float kAmplitude = 0.02f;

struct Variant {
    const char* name;
    bool displaced;
    bool accurate; ///< the Weingarten term
    bool adaptive; ///< the screen-space level of detail instead of the fixed level
};
constexpr Variant kVariants[] = {{"base", false, false, false},
                                 {"displaced", true, false, false},
                                 {"displaced-lod", true, false, true},
                                 {"weingarten", true, true, false}};

bool isSubdivPass(const std::string& name) {
    return name.rfind("subdiv.", 0) == 0;
}

/// The row's GPU figures from the profiler's passes recorded since
/// `firstPass` (each row is a new session, which numbers its frames from 0),
/// of frames `warmup` on.
void summarizeRow(const profiler::Profiler& profiler, size_t firstPass, uint64_t warmup, SubdivBenchRow& row) {
    std::map<uint64_t, double> subdiv, frame;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> perPass;
    const auto& passes = profiler.gpuPasses();
    for (size_t i = firstPass; i < passes.size(); ++i) {
        const auto& pass = passes[i];
        if (pass.frame < warmup) continue;
        const double ms = double(pass.durationNs) / 1e6;
        frame[pass.frame] += ms;
        if (!isSubdivPass(pass.name)) continue;
        subdiv[pass.frame] += ms;
        if (!perPass.count(pass.name)) order.push_back(pass.name);
        perPass[pass.name].push_back(ms);
        if (pass.stats && pass.name == "subdiv.draw") row.clipped = pass.stats->clippingInvocations;
    }
    auto values = [](const std::map<uint64_t, double>& m) {
        std::vector<double> v;
        for (const auto& [f, ms] : m) v.push_back(ms);
        return v;
    };
    const BenchSeries s = summarizeSeries(values(subdiv));
    row.gpuMsMedian = s.median;
    row.gpuMsMin = s.min;
    row.gpuMsMax = s.max;
    row.gpuFrameMsMedian = summarizeSeries(values(frame)).median;
    row.frames = uint32_t(subdiv.size());
    for (const std::string& name : order) row.passes.emplace_back(name, summarizeSeries(perPass[name]).median);
}

/// The scene a variant draws: the surfaces alone, still, no budget.
DemoOptions variantOptions(const DemoOptions& options, const std::string& backend, const Variant& variant,
                           float level) {
    DemoOptions run = options;
    run.backend = backend;
    run.scene = "characters";
    run.crowd = 0;
    run.bench.clear();
    run.subdiv.animate = false;
    run.subdiv.amplitude = variant.displaced ? options.subdiv.amplitude > 0.0f ? options.subdiv.amplitude : kAmplitude
                                             : 0.0f;
    run.subdiv.normals = variant.accurate ? 1u : 0u;
    run.subdiv.level = variant.adaptive ? std::nullopt : std::optional<float>(level);
    run.subdiv.levelEnd.reset();
    run.subdiv.budget = uint64_t(1) << 40;
    return run;
}

} // namespace

Status runSubdivBenchmark(const DemoOptions& options) {
    if (options.surfaces.empty()) return fail("--bench subdiv: give the surfaces with --model FILE.obj");
    auto& profiler = profiler::Profiler::global();
    profiler.setEnabled(true);
    const bool compare = options.backend == "all";
    std::vector<std::string> backends;
    if (compare)
        backends = {kComparisonReference, "streamout", "r2vb"};
    else if (!options.backend.empty())
        backends.push_back(options.backend);
    else
        backends.assign(std::begin(kBackendPreference), std::end(kBackendPreference));

    SubdivBenchSummary summary;
    summary.width = options.width;
    summary.height = options.height;
    summary.warmupFrames = options.warmup ? options.warmup : 3;
    summary.frames = options.frames ? options.frames : 10;
    summary.surfaces = options.surfaces;
    const float requested = options.subdiv.level.value_or(kSharedLevel);
    const std::filesystem::path traceDir = benchTraceDirectory(options);
    if (!traceDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(traceDir, ec);
        if (ec) return fail("--out-dir ", traceDir.string(), ": ", ec.message());
    }

    for (const std::string& backendName : backends) {
        profiler.clear();
        std::string tracePath;
        const RenderSession* traced = nullptr;
        std::vector<std::unique_ptr<SceneRun>> runs; // kept until the trace is written
        bool skipped = false;
        for (const Variant& variant : kVariants) {
            std::vector<float> levels = {std::min(requested, kSharedLevel)};
            if (requested > kSharedLevel) levels.push_back(requested);
            if (variant.adaptive) levels = {0.0f};
            for (const float level : levels) {
                const DemoOptions run = variantOptions(options, backendName, variant, level);
                auto created = SceneRun::create(run, summary.warmupFrames + summary.frames);
                if (!created) {
                    if (!compare) return created.error();
                    log::warning("skipping " + backendName + ": " + created.error().message);
                    summary.notes.push_back(backendName + " skipped: " + created.error().message);
                    skipped = true;
                    break;
                }
                SceneRun& scene = *created.value();
                RenderSession& session = scene.session();
                const auto& caps = session.capabilities();
                if (level > caps.maxTessFactor) continue;
                const size_t firstPass = profiler.gpuPasses().size();
                for (uint32_t f = 0; f < summary.warmupFrames + summary.frames; ++f) {
                    profiler.beginFrame(f);
                    scene.renderFrame(f, false);
                    profiler.endFrame();
                }
                session.finish();
                SubdivBenchRow& row = summary.rows.emplace_back();
                row.backend = caps.name;
                row.device = session.deviceName();
                row.driver = session.driverName();
                row.variant = variant.name;
                row.level = level;
                SubdivModels* surfaces = scene.scene().surfaces();
                row.triangles = surfaces ? surfaces->predictedTriangles() : 0;
                row.domains = surfaces ? surfaces->domainCount() : 0;
                summarizeRow(profiler, firstPass, summary.warmupFrames, row);
                if (surfaces && variant.displaced && summary.memory.coefficients == 0) {
                    const auto [samples, bytes] = surfaces->tileFigures();
                    summary.memory.coefficients = samples;
                    summary.memory.tileBytes = bytes;
                    // A vertex per sample (float3 position and normal) and two
                    // triangles of 32-bit indices; maps of R16 displacement and
                    // RGBA8 normals at 70% atlas coverage, with 4/3 for mips.
                    summary.memory.denseMeshBytes = samples * (24 + 6 * 4);
                    summary.memory.atlasBytes = uint64_t(double(samples) * (2 + 4) / 0.7 * 4.0 / 3.0);
                }
                if (!traceDir.empty()) {
                    tracePath = (traceDir / ("bench-subdiv-" + caps.name + ".json")).string();
                    row.trace = tracePath;
                }
                log::info(row.backend + " " + row.variant + ": " + std::to_string(row.gpuMsMedian) + " ms, " +
                          std::to_string(row.triangles) + " triangles");
                traced = &session;
                runs.push_back(std::move(created.value()));
            }
            if (skipped) break;
        }
        if (traced && !tracePath.empty())
            if (Status w = writeBenchTrace(profiler, tracePath, "tessera bench subdiv", *traced); !w) return w;
    }
    profiler.clear();
    if (summary.rows.empty()) return fail("--bench subdiv: no backend could run");
    summary.notes.push_back("GPU ms: the subdivision passes (refine, levels, draw) of every surface; triangles: the "
                            "CPU reference's prediction of what the draws tessellate");
    return writeBenchOutputs(options, subdivBenchJson(summary), subdivBenchTable(summary));
}

} // namespace tessera::demo
