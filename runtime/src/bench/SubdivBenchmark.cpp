#include "bench/SubdivBenchmark.h"

#include "bench/BenchDriver.h"
#include "bench/BenchSeries.h"
#include "bench/CharacterBenchFigures.h"
#include "bench/PassTimes.h"
#include "bench/SubdivBenchReport.h"
#include "bench/TerrainBenchReport.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/SceneRun.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <algorithm>

namespace tessera::runtime {
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

bool hasPrefix(const std::string& name, const char* prefix) {
    return name.rfind(prefix, 0) == 0;
}

BenchPlan subdivPlan() {
    BenchPlan plan;
    plan.name = "subdiv";
    plan.setting = setting::kSubdivBenchmark;
    plan.comparison = {kComparisonReference, "streamout", "r2vb", "meshshader"};
    return plan;
}

/// The row's GPU figures from the profiler's passes recorded since
/// `firstPass` (each row is a new session, which numbers its frames from 0),
/// of frames `warmup` on. `prefix` names the row's passes ("subdiv." or, for
/// the planar creature, "character.").
void summarizeRow(const profiler::Profiler& profiler, size_t firstPass, uint64_t warmup, const char* prefix,
                  SubdivBenchRow& row) {
    PassTimes times;
    const auto& passes = profiler.gpuPasses();
    for (size_t i = firstPass; i < passes.size(); ++i) {
        const auto& pass = passes[i];
        if (pass.frame < warmup) continue;
        const bool mine = hasPrefix(pass.name, prefix);
        times.add(pass, mine, mine);
        if (mine && pass.stats && (pass.name == "subdiv.draw" || pass.name == "character.tessellate"))
            row.clipped = profiler::generatedPrimitivesOf(*pass.stats);
    }
    const BenchSeries s = summarizeSeries(times.selectedTotals());
    row.gpuMsMedian = s.median;
    row.gpuMsMin = s.min;
    row.gpuMsMax = s.max;
    row.gpuFrameMsMedian = summarizeSeries(times.frameTotals()).median;
    row.frames = times.selectedFrames();
    row.passes = times.passMedians();
}

/// The scene a shape variant draws: the .obj surfaces alone, still, no budget.
Options variantOptions(const Options& options, const std::string& backend, const Variant& variant,
                           float level) {
    Options run = options;
    run.backend = backend;
    run.scene = "characters";
    run.crowd = 0;
    run.bench.clear();
    run.models.clear();
    run.subdiv.animate = false;
    run.subdiv.amplitude = variant.displaced ? options.subdiv.amplitude > 0.0f ? options.subdiv.amplitude : kAmplitude
                                             : 0.0f;
    run.subdiv.normals = variant.accurate ? 1u : 0u;
    run.subdiv.level = variant.adaptive ? std::nullopt : std::optional<float>(level);
    run.subdiv.levelEnd.reset();
    run.subdiv.budget = uint64_t(1) << 40;
    return run;
}

/// The creature drawn one way: `surface` catmull-clark (at subdiv `level`)
/// or planar (the single-pass path, drawn per character, at character
/// `level`; the two-pass path goes through the instanced crowd).
Options creatureOptions(const Options& options, const std::string& backend, const char* surface,
                            float level) {
    Options run = variantOptions(options, backend, kVariants[1], level);
    run.models = options.models;
    run.surfaces.clear();
    run.characterSurface = surface;
    run.characterPath = backend::CharacterPath::SinglePass;
    run.characterLevel = level;
    // The scene's own triangle budget (150,000 on lavapipe, 4 million on a
    // GPU) scales the creature's level down where it binds: its 15,000
    // domains at level 14.99 would be 6.7 million triangles, minutes a
    // frame on lavapipe. Both rows then draw what the budget allows.
    run.subdiv.budget = options.subdiv.budget;
    return run;
}

/// The planar level whose triangles come nearest `triangles` over
/// `cageTriangles` cage triangles, within [1, cap].
float equalTriangleLevel(uint64_t triangles, uint64_t cageTriangles, float cap) {
    float lo = 1.0f, hi = cap;
    for (int i = 0; i < 40; ++i) {
        const float mid = 0.5f * (lo + hi);
        (trianglesPerCageTriangle(mid) * cageTriangles < triangles ? lo : hi) = mid;
    }
    return hi;
}

/// A shape row's memory figures: the tiles, and the same samples as a dense
/// mesh (a vertex per sample: float3 position and normal, two triangles of
/// 32-bit indices) and as atlas maps (R16 displacement and RGBA8 normals at
/// 70% atlas coverage, 4/3 for mips).
SubdivMemory memoryOf(const SubdivModels& surfaces) {
    SubdivMemory m;
    const auto [samples, bytes] = surfaces.tileFigures();
    m.coefficients = samples;
    m.tileBytes = bytes;
    m.denseMeshBytes = samples * (24 + 6 * 4);
    m.atlasBytes = uint64_t(double(samples) * (2 + 4) / 0.7 * 4.0 / 3.0);
    return m;
}

/// A measured row and the run that drew it (kept until the trace is written).
struct Measured {
    std::unique_ptr<SceneRun> run;
    SubdivBenchRow row;
};

/// --bench subdiv on each of its backends: the shape variants at each
/// level, then the creature by both papers.
class SubdivBench {
public:
    explicit SubdivBench(const BenchDriver& driver) : mDriver(driver) {
        const Options& options = driver.options();
        mSummary.width = driver.width();
        mSummary.height = driver.height();
        mSummary.warmupFrames = driver.warmup();
        mSummary.frames = driver.frames();
        mSummary.surfaces = options.surfaces;
        mSummary.surfaces.insert(mSummary.surfaces.end(), options.models.begin(), options.models.end());
        mRequested = options.subdiv.level.value_or(kSharedLevel);
    }

    /// Every row of backend `name`, then its trace; an error ends the benchmark.
    Status runBackend(const std::string& name);
    /// The outputs.
    Status finish();

private:
    /// Draws the frames of `options` and summarizes the passes named `prefix`.
    Result<Measured> measure(const Options& options, const char* variant, float level, const char* prefix) const;
    /// Logs a measured row and keeps it; the error of one that failed.
    Status record(Result<Measured> measured);
    /// The .obj surfaces in every variant and level.
    Status measureShapes(const std::string& backend);
    /// The creature by the second paper (its Catmull-Clark cage and tiles)
    /// and by the first (its planar cage, displacement and normal maps) at
    /// equal triangle counts.
    Status measureCreature(const std::string& backend);

    const BenchDriver& mDriver;
    SubdivBenchSummary mSummary;
    float mRequested = kSharedLevel;
    std::vector<Measured> mDone; ///< this backend's rows; their sessions live until the trace is written
};

Result<Measured> SubdivBench::measure(const Options& options, const char* variant, float level,
                                      const char* prefix) const {
    auto& profiler = profiler::Profiler::global();
    const uint32_t total = mDriver.warmup() + mDriver.frames();
    auto created = SceneRun::create(options, total);
    if (!created) return created.error();
    Measured m{std::move(created.value()), {}};
    RenderSession& session = m.run->session();
    const size_t firstPass = profiler.gpuPasses().size();
    mDriver.renderFrames(0, total, [&m](uint32_t frame) { m.run->renderFrame(frame, false); });
    session.finish();
    m.row.backend = session.capabilities().name;
    m.row.device = session.deviceName();
    m.row.driver = session.driverName();
    m.row.variant = variant;
    m.row.level = level;
    summarizeRow(profiler, firstPass, mDriver.warmup(), prefix, m.row);
    return m;
}

Status SubdivBench::record(Result<Measured> measured) {
    if (!measured) return measured.error();
    const SubdivBenchRow& row = measured.value().row;
    log::info(row.backend + " " + row.variant + ": " + std::to_string(row.gpuMsMedian) + " ms, " +
              std::to_string(row.triangles) + " triangles");
    mDone.push_back(std::move(measured.value()));
    return {};
}

Status SubdivBench::measureShapes(const std::string& backend) {
    if (mDriver.options().surfaces.empty()) return {};
    const Options base = mDriver.runOptions(backend);
    for (const Variant& variant : kVariants) {
        std::vector<float> levels = {std::min(mRequested, kSharedLevel)};
        if (mRequested > kSharedLevel) levels.push_back(mRequested);
        if (variant.adaptive) levels = {0.0f};
        for (const float level : levels) {
            auto m = measure(variantOptions(base, backend, variant, level), variant.name, level, "subdiv.");
            // A level above the shared one is for backends that tessellate
            // that far; the others skip it.
            if (!m && level > kSharedLevel) continue;
            if (m && level > m.value().run->session().capabilities().maxTessFactor) continue;
            if (m) {
                const SubdivModels* surfaces = m.value().run->world().surfaces();
                m.value().row.triangles = surfaces ? surfaces->predictedTriangles() : 0;
                m.value().row.domains = surfaces ? surfaces->domainCount() : 0;
                if (surfaces && variant.displaced && mSummary.memory.coefficients == 0)
                    mSummary.memory = memoryOf(*surfaces);
            }
            if (Status ok = record(std::move(m)); !ok) return ok;
        }
    }
    return {};
}

Status SubdivBench::measureCreature(const std::string& backend) {
    const Options& options = mDriver.options();
    if (options.models.empty()) return {};
    const Options base = mDriver.runOptions(backend);
    const float level = std::min(mRequested, kSharedLevel);
    auto cc = measure(creatureOptions(base, backend, "catmull-clark", level), "creature-cc", level, "subdiv.");
    if (!cc) return cc.error();
    const SubdivCharacters* characters = cc.value().run->world().subdivCharacters();
    if (!characters)
        return failSetting(setting::kSubdivBenchmark, ": ", reporterFor(options).name(setting::kModels), " ",
                           options.models.front(), " is not a creature");
    SubdivBenchRow& row = cc.value().row;
    row.triangles = characters->predictedTriangles();
    // The level the budget left (the fixed level after scaling).
    if (!characters->draws().empty()) row.level = characters->draws().front().info.uniforms.lod.w;
    row.domains = characters->domainCount();
    const float planarLevel = equalTriangleLevel(row.triangles, characters->cageTriangles(),
                                                 cc.value().run->session().maxCharacterLevel());
    if (Status ok = record(std::move(cc)); !ok) return ok;
    auto planar = measure(creatureOptions(base, backend, "planar", planarLevel), "creature-planar", planarLevel,
                          "character.");
    if (planar) planar.value().row.triangles = planar.value().run->session().lastFrameReport().characterTriangles;
    return record(std::move(planar));
}

Status SubdivBench::runBackend(const std::string& name) {
    profiler::Profiler::global().clear();
    mDone.clear();
    Status ran = measureShapes(name);
    if (ran) ran = measureCreature(name);
    if (!ran)
        if (Status skipped = mDriver.skip(name, ran.error(), mSummary.notes); !skipped) return skipped;
    if (mDone.empty()) return {};
    const std::string trace = mDriver.tracePath("subdiv-" + name);
    for (Measured& m : mDone) {
        m.row.trace = trace;
        mSummary.rows.push_back(m.row);
    }
    Status written = mDriver.writeTrace(trace, mDone.back().run->session());
    mDone.clear();
    return written;
}

Status SubdivBench::finish() {
    if (!mSummary.rows.empty())
        mSummary.notes.push_back(
            "GPU ms: the subdivision passes (refine, levels, draw) of every surface, or the planar creature's "
            "character passes (skin, tessellate); triangles: the CPU reference's prediction for surfaces, the frame "
            "report's for the planar creature");
    return mDriver.finish(mSummary.rows.size(), subdivBenchJson(mSummary), subdivBenchTable(mSummary));
}

} // namespace

Status runSubdivBenchmark(const Options& options) {
    if (options.surfaces.empty() && options.models.empty()) {
        const std::string model = reporterFor(options).name(setting::kModels);
        return failSetting(setting::kSubdivBenchmark, ": give the surfaces with ", model,
                           " FILE.obj (and creatures with ", model, " FILE.glb)");
    }
    auto driver = BenchDriver::start(options, subdivPlan());
    if (!driver) return driver.error();
    SubdivBench bench(driver.value());
    for (const std::string& backend : driver.value().backends())
        if (Status ok = bench.runBackend(backend); !ok) return ok;
    return bench.finish();
}

} // namespace tessera::runtime
