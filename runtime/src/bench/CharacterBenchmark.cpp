#include "bench/CharacterBenchmark.h"

#include "bench/BenchDriver.h"
#include "bench/BenchSeries.h"
#include "bench/CharacterBenchFigures.h"
#include "bench/CharacterBenchReport.h"
#include "bench/PassTimes.h"
#include "bench/TerrainBenchReport.h"
#include "characters/LodSettings.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/runtime/World.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <algorithm>

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

BenchPlan characterPlan() {
    BenchPlan plan;
    plan.name = "characters";
    plan.setting = setting::kCharacterBenchmark;
    plan.comparison = {kComparisonReference, "r2vb", "streamout", "meshshader"};
    return plan;
}

bool isPathPass(const std::string& name, backend::CharacterPath path) {
    if (path == backend::CharacterPath::TwoPass) return name == "character.skin" || name == "character.tessellate";
    return name == "character.singlePass";
}

/// The row's GPU figures from the profiler's passes of frames [first, end).
void summarizeRow(const profiler::Profiler& profiler, uint64_t first, uint64_t end, backend::CharacterPath path,
                  CharacterBenchRow& row) {
    PassTimes times;
    uint64_t statsFrame = 0;
    for (const auto& pass : profiler.gpuPasses()) {
        if (pass.frame < first || pass.frame >= end) continue;
        times.add(pass, isPathPass(pass.name, path), true);
        const bool drawing = pass.name == "character.tessellate" || pass.name == "character.singlePass";
        if (drawing && pass.stats && pass.frame >= statsFrame) {
            statsFrame = pass.frame;
            row.clippingInvocations = profiler::generatedPrimitivesOf(*pass.stats);
        }
    }
    const BenchSeries c = summarizeSeries(times.selectedTotals());
    row.characterMsMedian = c.median;
    row.characterMsMin = c.min;
    row.characterMsMax = c.max;
    row.gpuFrameMsMedian = summarizeSeries(times.frameTotals()).median;
    row.frames = times.selectedFrames();
    row.passes = times.passMedians();
}

/// What every row of one backend draws with.
struct RowSetup {
    scene::Camera camera;
    terrain::TessellationSettings settings;
    float top = 0.0f;  ///< the backend's largest character level
    std::string trace; ///< the backend's trace file, or ""
};

/// --bench characters on each of its backends: every level the backend
/// reaches, each drawn two-pass and single-pass.
class CharacterBench {
public:
    CharacterBench(const BenchDriver& driver, World& world, CharacterPopulation& crowd)
        : mDriver(driver), mGround(world.terrain()), mDrawn(world.ground()), mCrowd(crowd) {}

    /// The run's settings and levels, with a note when backends that
    /// tessellate further draw a level the others do not.
    void describe();
    /// Every row of backend `name`; an error ends the benchmark.
    Status runBackend(const std::string& name);
    /// The figures of every asset, then the outputs.
    Status finish();

private:
    /// The row of `path` at `level`: warm-up and measured frames, then their figures.
    void measureRow(RenderSession& session, const RowSetup& setup, float level, backend::CharacterPath path);

    const BenchDriver& mDriver;
    terrain::Terrain& mGround;
    terrain::DrawnSurface& mDrawn; ///< where the characters stand
    CharacterPopulation& mCrowd;
    CharacterBenchSummary mSummary;
    float mRequested = 0.0f, mShared = 0.0f;
    uint32_t mFrameIndex = 0;
};

void CharacterBench::describe() {
    CharacterBenchSummary& s = mSummary;
    s.width = mDriver.width();
    s.height = mDriver.height();
    s.warmupFrames = mDriver.warmup();
    s.frames = mDriver.frames();
    s.poseSeconds = kPoseSeconds;
    s.paperLevel = paperAmplificationLevel(64.0f);
    s.paperLevelAmplification = double(trianglesPerCageTriangle(float(s.paperLevel)));
    mRequested = mDriver.options().characterLevel.value_or(kHardwareLevel);
    mShared = std::min(mRequested, kSharedMaxLevel);
    s.sharedLevel = mShared;
    s.tableLevel = mShared;
    if (mRequested > mShared)
        s.notes.push_back("every backend draws at level " + formatNumber(mShared) +
                          ", the emulated tessellator's maximum; backends that tessellate further also at " +
                          formatNumber(mRequested));
}

Status CharacterBench::runBackend(const std::string& name) {
    const Options run = mDriver.runOptions(name);
    profiler::Profiler::global().clear();
    auto created = RenderSession::create(run, mGround);
    if (!created) return mDriver.skip(name, created.error(), mSummary.notes);
    RenderSession& session = *created.value();
    const Options& options = mDriver.options();
    RowSetup setup;
    setup.top = session.maxCharacterLevel();
    if (!mDriver.comparing() && options.characterLevel && *options.characterLevel > setup.top)
        return failSetting(setting::kCharacterLevel, " ", formatNumber(*options.characterLevel), ": backend ",
                           session.capabilities().name, " tessellates up to level ", formatNumber(setup.top));
    std::vector<float> levels = {std::min(mShared, setup.top)};
    if (mRequested > levels.front() && mRequested <= setup.top) levels.push_back(mRequested);
    session.setTerrainVisible(options.terrain);
    auto settings = session.resolveTessellation(run);
    if (!settings) return settings.error();
    setup.settings = settings.value();
    if (Status ok = session.createCharacters(mCrowd.assets()); !ok) return ok.error();
    setup.camera.setPose(options.camera.value_or(mCrowd.orbitPose(kPoseSeconds)));
    setup.camera.setAspect(float(session.width()) / float(session.height()));
    session.updateGround(mDrawn, setup.camera, setup.settings);
    setup.trace = mDriver.tracePath("characters-" + session.capabilities().name);
    for (const float level : levels) {
        mSummary.tableLevel = std::max(mSummary.tableLevel, double(level));
        for (auto path : {backend::CharacterPath::TwoPass, backend::CharacterPath::SinglePass})
            measureRow(session, setup, level, path);
    }
    return mDriver.writeTrace(setup.trace, session);
}

void CharacterBench::measureRow(RenderSession& session, const RowSetup& setup, float level,
                                backend::CharacterPath path) {
    auto& profiler = profiler::Profiler::global();
    const uint32_t first = mFrameIndex;
    const uint64_t rowStartNs = profiler.nowNs();
    const bool displacement = mDriver.options().displacement;
    const glm::vec3 clearColor = mDriver.options().clearColor;
    mFrameIndex = mDriver.renderFrames(first, mSummary.warmupFrames + mSummary.frames, [&](uint32_t frame) {
        // The paths themselves are measured: every character in view
        // tessellated at the row's level, whatever the budget.
        mCrowd.update(kPoseSeconds, setup.camera, {session.height(), setup.top, level, measureEveryCharacter()});
        const backend::CharacterDrawInfo draw{mCrowd.items(), path, displacement};
        session.renderFrame(frame, setup.camera, setup.settings, clearColor, false, false, &draw);
    });
    session.finish();
    CharacterBenchRow& row = mSummary.rows.emplace_back();
    row.backend = session.capabilities().name;
    row.device = session.deviceName();
    row.driver = session.driverName();
    row.path = backend::toString(path);
    row.level = level;
    row.trace = setup.trace;
    const backend::FrameReport report = session.lastFrameReport();
    row.charactersDrawn = report.charactersDrawn;
    row.cageTriangles = report.characterCageTriangles;
    row.triangles = report.characterTriangles;
    row.intermediateBytes = report.intermediateBytes;
    summarizeRow(profiler, first + mSummary.warmupFrames, mFrameIndex, path, row);
    mSummary.crowdMembers = std::max(mSummary.crowdMembers, row.charactersDrawn);
    mDriver.markRow(row.path + " level " + formatNumber(level), first, rowStartNs);
    log::info(row.backend + " " + row.path + " level " + formatNumber(level) + ": " +
              std::to_string(row.characterMsMedian) + " ms, " + std::to_string(row.triangles) + " triangles");
}

Status CharacterBench::finish() {
    if (!mSummary.rows.empty())
        for (const CrowdAsset& asset : mCrowd.assets().all())
            mSummary.assets.push_back(
                assetFigures(asset, mShared, float(mSummary.paperLevel), float(mSummary.tableLevel)));
    return mDriver.finish(mSummary.rows.size(), characterBenchJson(mSummary), characterBenchTable(mSummary));
}

} // namespace

Status runCharacterBenchmark(const Options& options) {
    Options base = options;
    base.scene = "characters";
    auto driver = BenchDriver::start(base, characterPlan());
    if (!driver) return driver.error();
    auto loaded = World::load(base, 1);
    if (!loaded) return loaded.error();
    CharacterPopulation* crowd = loaded.value()->characters();
    if (!crowd || crowd->assets().empty()) {
        const Reporter& names = reporterFor(options);
        return failSetting(setting::kCharacterBenchmark, ": no characters to draw (", names.name(setting::kCreatures),
                           " 0 and no ", names.name(setting::kModels), ")");
    }
    CharacterBench bench(driver.value(), *loaded.value(), *crowd);
    bench.describe();
    for (const std::string& backend : driver.value().backends())
        if (Status ok = bench.runBackend(backend); !ok) return ok;
    return bench.finish();
}

} // namespace tessera::runtime
