#include "CharacterBenchmark.h"

#include "tessera/runtime/BackendSelection.h"
#include "BenchSeries.h"
#include "CharacterBenchFigures.h"
#include "CharacterBenchReport.h"
#include "tessera/runtime/World.h"
#include "LodSettings.h"
#include "BenchOutputs.h"
#include "tessera/runtime/RenderSession.h"
#include "TerrainBenchReport.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/profiler/TraceWriter.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace tessera::runtime {
namespace {

/// Every frame poses the crowd at this animation time: mid-stride for the
/// walkers, so the skinning is not the rest pose, and the same work each frame.
constexpr double kPoseSeconds = 1.0;
/// The emulated tessellator's largest level: the level all backends share.
/// Its amplification (337x) is the paper's within one step of the odd levels.
constexpr float kSharedMaxLevel = tessellator::ContinuousLevel::kMaxLevel;
/// The extra level of backends that tessellate further (hulldomain) when
/// --character-level is not given: about 4.8x the shared level's triangles.
constexpr float kHardwareLevel = 32.0f;

bool isPathPass(const std::string& name, backend::CharacterPath path) {
    if (path == backend::CharacterPath::TwoPass) return name == "character.skin" || name == "character.tessellate";
    return name == "character.singlePass";
}

/// The row's GPU figures from the profiler's passes of frames [first, end).
void summarizeRow(const profiler::Profiler& profiler, uint64_t first, uint64_t end, backend::CharacterPath path,
                  CharacterBenchRow& row) {
    std::map<uint64_t, double> character, frame;
    std::vector<std::string> order;
    std::map<std::string, std::vector<double>> perPass;
    uint64_t statsFrame = 0;
    for (const auto& pass : profiler.gpuPasses()) {
        if (pass.frame < first || pass.frame >= end) continue;
        const double ms = double(pass.durationNs) / 1e6;
        frame[pass.frame] += ms;
        if (isPathPass(pass.name, path)) character[pass.frame] += ms;
        if (!perPass.count(pass.name)) order.push_back(pass.name);
        perPass[pass.name].push_back(ms);
        const bool drawing = pass.name == "character.tessellate" || pass.name == "character.singlePass";
        if (drawing && pass.stats && pass.frame >= statsFrame) {
            statsFrame = pass.frame;
            row.clippingInvocations = pass.stats->clippingInvocations;
        }
    }
    auto values = [](const std::map<uint64_t, double>& m) {
        std::vector<double> v;
        for (const auto& [f, ms] : m) v.push_back(ms);
        return v;
    };
    const BenchSeries c = summarizeSeries(values(character));
    row.characterMsMedian = c.median;
    row.characterMsMin = c.min;
    row.characterMsMax = c.max;
    row.gpuFrameMsMedian = summarizeSeries(values(frame)).median;
    row.frames = static_cast<uint32_t>(character.size());
    for (const std::string& name : order) row.passes.emplace_back(name, summarizeSeries(perPass[name]).median);
}

Status writeOutputs(const Options& options, const CharacterBenchSummary& summary) {
    const std::string json = characterBenchJson(summary);
    const std::string table = characterBenchTable(summary);
    return writeBenchOutputs(options, json, table);
}

} // namespace

Status runCharacterBenchmark(const Options& options) {
    auto& profiler = profiler::Profiler::global();
    profiler.setEnabled(true);
    Options base = options;
    base.scene = "characters";
    auto loaded = World::load(base, 1);
    if (!loaded) return loaded.error();
    terrain::Terrain& ground = loaded.value()->terrain();
    CharacterPopulation* crowd = loaded.value()->characters();
    if (!crowd || crowd->assets().empty())
        return fail("--bench characters: no characters to draw (--crowd 0 and no --model)");

    const bool compare = options.backend == "all";
    std::vector<std::string> backends;
    if (compare)
        backends = {kComparisonReference, "r2vb", "streamout"};
    else if (!options.backend.empty())
        backends.push_back(options.backend);
    else
        backends.assign(std::begin(kBackendPreference), std::end(kBackendPreference));

    CharacterBenchSummary summary;
    summary.width = options.width;
    summary.height = options.height;
    summary.warmupFrames = options.warmup ? options.warmup : 3;
    summary.frames = options.frames ? options.frames : 10;
    summary.poseSeconds = kPoseSeconds;
    summary.paperLevel = paperAmplificationLevel(64.0f);
    summary.paperLevelAmplification = double(trianglesPerCageTriangle(float(summary.paperLevel)));
    const float requested = options.characterLevel.value_or(kHardwareLevel);
    const float shared = std::min(requested, kSharedMaxLevel);
    summary.sharedLevel = shared;
    summary.tableLevel = shared;
    if (requested > shared)
        summary.notes.push_back("every backend draws at level " + formatNumber(shared) +
                                ", the emulated tessellator's maximum; backends that tessellate further also at " +
                                formatNumber(requested));

    const std::filesystem::path traceDir = benchTraceDirectory(options);
    if (!traceDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(traceDir, ec);
        if (ec) return fail("--out-dir ", traceDir.string(), ": ", ec.message());
    }

    uint32_t frameIndex = 0;
    for (const std::string& backendName : backends) {
        Options run = base;
        run.backend = backendName;
        profiler.clear();
        auto created = RenderSession::create(run, ground);
        if (!created) {
            if (!compare && backends.size() == 1) return created.error();
            log::warning("skipping " + backendName + ": " + created.error().message);
            summary.notes.push_back(backendName + " skipped: " + created.error().message);
            continue;
        }
        RenderSession& session = *created.value();
        const auto& caps = session.capabilities();
        const float top = session.maxCharacterLevel();
        if (!compare && options.characterLevel && *options.characterLevel > top)
            return fail("--character-level ", formatNumber(*options.characterLevel), ": backend ", caps.name,
                        " tessellates up to level ", formatNumber(top));
        std::vector<float> levels = {std::min(shared, top)};
        if (requested > levels.front() && requested <= top) levels.push_back(requested);
        session.setTerrainVisible(options.terrain);
        auto settings = session.resolveTessellation(run);
        if (!settings) return settings.error();
        if (Status ok = session.createCharacters(crowd->assets()); !ok) return ok.error();

        scene::Camera camera;
        camera.setPose(options.camera.value_or(crowd->orbitPose(kPoseSeconds)));
        camera.setAspect(float(session.width()) / float(session.height()));
        const std::string tracePath =
            traceDir.empty() ? std::string() : (traceDir / ("bench-characters-" + caps.name + ".json")).string();
        for (const float level : levels) {
            summary.tableLevel = std::max(summary.tableLevel, double(level));
            for (auto path : {backend::CharacterPath::TwoPass, backend::CharacterPath::SinglePass}) {
                const uint32_t first = frameIndex;
                const uint64_t rowStartNs = profiler.nowNs();
                for (uint32_t f = 0; f < summary.warmupFrames + summary.frames; ++f, ++frameIndex) {
                    profiler.beginFrame(frameIndex);
                    // The paths themselves are measured: every character in view
                    // tessellated at the row's level, whatever the budget.
                    crowd->update(kPoseSeconds, camera, {session.height(), top, level, measureEveryCharacter()});
                    const backend::CharacterDrawInfo draw{crowd->items(), path, options.displacement};
                    session.renderFrame(frameIndex, camera, settings.value(), options.clearColor, false, false, &draw);
                    profiler.endFrame();
                }
                session.finish();
                CharacterBenchRow& row = summary.rows.emplace_back();
                row.backend = caps.name;
                row.device = session.deviceName();
                row.driver = session.driverName();
                row.path = backend::toString(path);
                row.level = level;
                row.trace = tracePath;
                const backend::FrameReport report = session.lastFrameReport();
                row.charactersDrawn = report.charactersDrawn;
                row.cageTriangles = report.characterCageTriangles;
                row.triangles = report.characterTriangles;
                row.intermediateBytes = report.intermediateBytes;
                summarizeRow(profiler, first + summary.warmupFrames, frameIndex, path, row);
                summary.crowdMembers = std::max(summary.crowdMembers, row.charactersDrawn);
                // One slice per row on the CPU track, so the trace reads as the table's rows.
                const std::string label = row.path + " level " + formatNumber(level);
                profiler.recordCpu({internBenchName(label), profiler::Profiler::currentThreadId(), first, rowStartNs,
                                    profiler.nowNs() - rowStartNs, 0});
                log::info(row.backend + " " + row.path + " level " + formatNumber(level) + ": " +
                          std::to_string(row.characterMsMedian) + " ms, " + std::to_string(row.triangles) +
                          " triangles");
            }
        }
        if (!tracePath.empty()) {
            if (auto w = writeBenchTrace(profiler, tracePath, "tessera bench characters", session); !w) return w;
        }
    }
    profiler.clear();
    if (summary.rows.empty()) return fail("--bench characters: no backend could run");
    for (const CrowdAsset& asset : crowd->assets().all())
        summary.assets.push_back(assetFigures(asset, shared, float(summary.paperLevel), float(summary.tableLevel)));
    return writeOutputs(options, summary);
}

} // namespace tessera::runtime
