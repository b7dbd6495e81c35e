#include "SubdivBenchmark.h"

#include "tessera/runtime/BackendSelection.h"
#include "BenchOutputs.h"
#include "BenchSeries.h"
#include "tessera/runtime/SceneRun.h"
#include "SubdivBenchReport.h"
#include "CharacterBenchFigures.h"
#include "TerrainBenchReport.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <algorithm>
#include <filesystem>
#include <map>

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

/// The row's GPU figures from the profiler's passes recorded since
/// `firstPass` (each row is a new session, which numbers its frames from 0),
/// of frames `warmup` on.
/// `prefix` names the row's passes ("subdiv." or, for the planar creature,
/// "character.").
void summarizeRow(const profiler::Profiler& profiler, size_t firstPass, uint64_t warmup, const char* prefix,
                  SubdivBenchRow& row) {
    std::map<uint64_t, double> subdiv, frame;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> perPass;
    const auto& passes = profiler.gpuPasses();
    for (size_t i = firstPass; i < passes.size(); ++i) {
        const auto& pass = passes[i];
        if (pass.frame < warmup) continue;
        const double ms = double(pass.durationNs) / 1e6;
        frame[pass.frame] += ms;
        if (!hasPrefix(pass.name, prefix)) continue;
        subdiv[pass.frame] += ms;
        if (!perPass.count(pass.name)) order.push_back(pass.name);
        perPass[pass.name].push_back(ms);
        if (pass.stats && (pass.name == "subdiv.draw" || pass.name == "character.tessellate"))
            row.clipped = pass.stats->clippingInvocations;
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

/// A measured row and the run that drew it (kept until the trace is written).
struct Measured {
    std::unique_ptr<SceneRun> run;
    SubdivBenchRow row;
};

/// Draws `warmup` + `frames` frames of `options` and summarizes the passes
/// named `prefix`.
Result<Measured> measure(const Options& options, const char* variant, float level, const char* prefix,
                         uint32_t warmup, uint32_t frames) {
    auto& profiler = profiler::Profiler::global();
    auto created = SceneRun::create(options, warmup + frames);
    if (!created) return created.error();
    Measured m{std::move(created.value()), {}};
    RenderSession& session = m.run->session();
    const size_t firstPass = profiler.gpuPasses().size();
    for (uint32_t f = 0; f < warmup + frames; ++f) {
        profiler.beginFrame(f);
        m.run->renderFrame(f, false);
        profiler.endFrame();
    }
    session.finish();
    m.row.backend = session.capabilities().name;
    m.row.device = session.deviceName();
    m.row.driver = session.driverName();
    m.row.variant = variant;
    m.row.level = level;
    summarizeRow(profiler, firstPass, warmup, prefix, m.row);
    return m;
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

} // namespace

Status runSubdivBenchmark(const Options& options) {
    if (options.surfaces.empty() && options.models.empty())
        return fail("--bench subdiv: give the surfaces with --model FILE.obj (and creatures with --model FILE.glb)");
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
    summary.surfaces.insert(summary.surfaces.end(), options.models.begin(), options.models.end());
    const float requested = options.subdiv.level.value_or(kSharedLevel);
    const std::filesystem::path traceDir = benchTraceDirectory(options);
    if (!traceDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(traceDir, ec);
        if (ec) return fail("--out-dir ", traceDir.string(), ": ", ec.message());
    }
    const uint32_t warmup = summary.warmupFrames, frames = summary.frames;

    for (const std::string& backendName : backends) {
        profiler.clear();
        std::vector<Measured> done; // their sessions stay alive until the trace is written
        auto record = [&](Result<Measured> measured) -> Status {
            if (!measured) return measured.error();
            const SubdivBenchRow& row = measured.value().row;
            log::info(row.backend + " " + row.variant + ": " + std::to_string(row.gpuMsMedian) + " ms, " +
                      std::to_string(row.triangles) + " triangles");
            done.push_back(std::move(measured.value()));
            return {};
        };
        Status ran = [&]() -> Status {
            for (const Variant& variant : kVariants) {
                if (options.surfaces.empty()) break;
                std::vector<float> levels = {std::min(requested, kSharedLevel)};
                if (requested > kSharedLevel) levels.push_back(requested);
                if (variant.adaptive) levels = {0.0f};
                for (const float level : levels) {
                    auto m = measure(variantOptions(options, backendName, variant, level), variant.name, level,
                                     "subdiv.", warmup, frames);
                    // A level above the shared one is for backends that
                    // tessellate that far; the others skip it.
                    if (!m && level > kSharedLevel) continue;
                    if (m && level > m.value().run->session().capabilities().maxTessFactor) continue;
                    if (m) {
                        const SubdivModels* surfaces = m.value().run->world().surfaces();
                        m.value().row.triangles = surfaces ? surfaces->predictedTriangles() : 0;
                        m.value().row.domains = surfaces ? surfaces->domainCount() : 0;
                        if (surfaces && variant.displaced && summary.memory.coefficients == 0)
                            summary.memory = memoryOf(*surfaces);
                    }
                    if (Status ok = record(std::move(m)); !ok) return ok;
                }
            }
            if (options.models.empty()) return {};
            // The creature by the second paper (its Catmull-Clark cage and
            // tiles) and by the first (its planar cage, displacement and
            // normal maps) at equal triangle counts.
            const float level = std::min(requested, kSharedLevel);
            auto cc = measure(creatureOptions(options, backendName, "catmull-clark", level), "creature-cc", level,
                              "subdiv.", warmup, frames);
            if (!cc) return cc.error();
            const SubdivCharacters* characters = cc.value().run->world().subdivCharacters();
            if (!characters) return fail("--bench subdiv: --model ", options.models.front(), " is not a creature");
            cc.value().row.triangles = characters->predictedTriangles();
            // The level the budget left (the fixed level after scaling).
            if (!characters->draws().empty()) cc.value().row.level = characters->draws().front().info.uniforms.lod.w;
            cc.value().row.domains = characters->domainCount();
            const uint64_t triangles = cc.value().row.triangles;
            const uint64_t cageTriangles = characters->cageTriangles();
            const float cap = cc.value().run->session().maxCharacterLevel();
            if (Status ok = record(std::move(cc)); !ok) return ok;
            const float planarLevel = equalTriangleLevel(triangles, cageTriangles, cap);
            auto planar = measure(creatureOptions(options, backendName, "planar", planarLevel), "creature-planar",
                                  planarLevel, "character.", warmup, frames);
            if (planar) {
                const backend::FrameReport report = planar.value().run->session().lastFrameReport();
                planar.value().row.triangles = report.characterTriangles;
            }
            return record(std::move(planar));
        }();
        if (!ran) {
            if (!compare) return ran;
            log::warning("skipping " + backendName + ": " + ran.error().message);
            summary.notes.push_back(backendName + " skipped: " + ran.error().message);
        }
        if (done.empty()) continue;
        const std::string tracePath =
            traceDir.empty() ? std::string() : (traceDir / ("bench-subdiv-" + backendName + ".json")).string();
        for (Measured& m : done) {
            m.row.trace = tracePath;
            summary.rows.push_back(m.row);
        }
        if (!tracePath.empty())
            if (Status w = writeBenchTrace(profiler, tracePath, "tessera bench subdiv", done.back().run->session()); !w)
                return w;
    }
    profiler.clear();
    if (summary.rows.empty()) return fail("--bench subdiv: no backend could run");
    summary.notes.push_back("GPU ms: the subdivision passes (refine, levels, draw) of every surface, or the planar "
                            "creature's character passes (skin, tessellate); triangles: the CPU reference's "
                            "prediction for surfaces, the frame report's for the planar creature");
    return writeBenchOutputs(options, subdivBenchJson(summary), subdivBenchTable(summary));
}

} // namespace tessera::runtime
