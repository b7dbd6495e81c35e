#include "bench/TerrainBenchmark.h"

#include "bench/BenchDriver.h"
#include "bench/TerrainBenchReport.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/runtime/World.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tessera::runtime {

namespace {

/// The emulated tessellator's largest level: the common cap of --backend all.
constexpr float kComparisonMaxLevel = tessellator::ContinuousLevel::kMaxLevel;

BenchPlan terrainPlan() {
    BenchPlan plan;
    plan.name = "terrain";
    plan.setting = setting::kTerrainBenchmark;
    plan.comparison = {kComparisonReference, "r2vb", "streamout", "meshshader"};
    plan.everyDevice = true;
    return plan;
}

/// A level as the messages and notes print it.
std::string level(float value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

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

/// The options of each row of one backend: every mode it draws, adaptive
/// once per metric (or only the options' metric), each metric at its
/// default target unless the options give one.
std::vector<Options> benchRuns(const Options& options, const backend::BackendCapabilities& caps) {
    std::vector<Options> runs;
    for (auto mode : {terrain::TerrainMode::LowRes, terrain::TerrainMode::Continuous, terrain::TerrainMode::Adaptive}) {
        if (!caps.drawsTerrainMode(mode)) continue;
        std::vector<std::optional<terrain::TessMetric>> metrics = {options.tessellation.metric};
        if (mode == terrain::TerrainMode::Adaptive && !options.tessellation.metric)
            metrics = {terrain::TessMetric::ScreenEdge, terrain::TessMetric::HeightDetail,
                       terrain::TessMetric::Distance, terrain::TessMetric::Silhouette};
        for (auto metric : metrics) {
            Options run = options;
            run.terrainMode = mode;
            run.tessellation.metric = metric;
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
        r.fragmentShaderInvocations = stats->fragmentShaderInvocations;
        r.taskShaderInvocations = stats->taskShaderInvocations;
        r.meshShaderInvocations = stats->meshShaderInvocations;
        r.meshPrimitives = stats->meshPrimitivesGenerated;
    }
    const std::string terrainPass = std::string("terrain.") + terrain::toString(settings.mode);
    for (const profiler::PassSummary& pass : summary.passes) {
        TerrainBenchPass p;
        p.name = pass.name;
        p.gpuMsMedian = pass.medianMs;
        if (pass.statsMedianFrame) {
            p.clippingInvocations = profiler::generatedPrimitivesOf(*pass.statsMedianFrame);
            p.vertexShaderInvocations = pass.statsMedianFrame->vertexShaderInvocations;
            p.tessEvaluationInvocations = pass.statsMedianFrame->tessEvaluationInvocations;
            p.geometryShaderInvocations = pass.statsMedianFrame->geometryShaderInvocations;
            p.fragmentShaderInvocations = pass.statsMedianFrame->fragmentShaderInvocations;
        }
        if (p.name == terrainPass) r.clippingInvocations = p.clippingInvocations;
        r.passes.push_back(std::move(p));
    }
    r.intermediateBytes = session.lastFrameReport().intermediateBytes;
    return r;
}

/// --bench terrain on each device and backend: both views, every row of
/// benchRuns, in each look asked for.
class TerrainBench {
public:
    TerrainBench(const BenchDriver& driver, terrain::Terrain& ground) : mDriver(driver), mGround(ground) {
        mLooks = {driver.options().look};
        // --look both: each row twice, plain then full, on the same session.
        if (driver.options().benchBothLooks) mLooks = {backend::Look::Plain, backend::Look::Full};
    }

    /// A note for the table under the comparison.
    void note(std::string text) { mNotes.push_back(std::move(text)); }
    /// Every row of `backend` on `device`; an error ends the benchmark.
    Status runBackend(const std::string& device, const std::string& backend);
    /// The JSON and the tables.
    Status finish() const;

private:
    /// `run`'s levels as every row of `caps`'s backend draws them: the
    /// comparison's common cap, and the backend's maximum instead of an
    /// error for a level above it.
    Options cappedLevels(Options run, const backend::BackendCapabilities& caps) const;
    /// The modes the backend does not draw, as a note.
    void noteMissingModes(const RenderSession& session);
    /// One row: warm-up and measured frames from `camera` with `settings`
    /// in `look`, then its record.
    void measureRow(RenderSession& session, const scene::Camera& camera, const char* view,
                    const terrain::TessellationSettings& settings, backend::Look look, const std::string& trace);

    const BenchDriver& mDriver;
    terrain::Terrain& mGround;
    std::vector<backend::Look> mLooks;
    std::vector<TerrainBenchRecord> mRecords;
    std::vector<std::string> mNotes;
    uint32_t mFrameIndex = 0;
};

Options TerrainBench::cappedLevels(Options run, const backend::BackendCapabilities& caps) const {
    TessellationOptions& levels = run.tessellation;
    const float common = mDriver.comparing() ? kComparisonMaxLevel : caps.maxTessFactor;
    levels.maxLevel = std::min(levels.maxLevel.value_or(common), caps.maxTessFactor);
    levels.continuousLevel =
        std::min({levels.continuousLevel.value_or(terrain::TessellationSettings{}.continuousLevel), common,
                  caps.maxTessFactor});
    return run;
}

void TerrainBench::noteMissingModes(const RenderSession& session) {
    const auto& caps = session.capabilities();
    std::string modes;
    for (auto mode : {terrain::TerrainMode::Continuous, terrain::TerrainMode::Adaptive})
        if (!caps.drawsTerrainMode(mode)) modes += (modes.empty() ? "" : ", ") + std::string(terrain::toString(mode));
    if (!modes.empty()) mNotes.push_back(caps.name + " on " + session.deviceName() + " does not draw " + modes);
}

Status TerrainBench::runBackend(const std::string& device, const std::string& backend) {
    profiler::Profiler::global().clear();
    auto created = RenderSession::create(mDriver.runOptions(backend, device), mGround);
    if (!created) return mDriver.skip(backend, created.error(), mNotes, device);
    RenderSession& session = *created.value();
    const auto& caps = session.capabilities();
    const Options run = cappedLevels(mDriver.runOptions(backend, device), caps);
    noteMissingModes(session);
    const std::string trace =
        mDriver.tracePath(caps.name + (mDriver.devices().size() > 1 ? "-device" + device : std::string()));
    const size_t firstRecord = mRecords.size();
    for (const BenchView& view : benchViews(mGround)) {
        scene::Camera camera;
        camera.setPose(view.pose);
        camera.setAspect(float(session.width()) / float(session.height()));
        for (const Options& row : benchRuns(run, caps)) {
            auto settings = session.resolveTessellation(row);
            if (!settings) return settings.error();
            for (const backend::Look look : mLooks) measureRow(session, camera, view.name, settings.value(), look, trace);
        }
    }
    return mRecords.size() > firstRecord ? mDriver.writeTrace(trace, session) : Status{};
}

void TerrainBench::measureRow(RenderSession& session, const scene::Camera& camera, const char* view,
                              const terrain::TessellationSettings& settings, backend::Look look,
                              const std::string& trace) {
    auto& profiler = profiler::Profiler::global();
    session.setLook(look);
    const uint32_t first = mFrameIndex;
    const uint64_t rowStartNs = profiler.nowNs();
    const glm::vec3 clearColor = mDriver.options().clearColor;
    mFrameIndex = mDriver.renderFrames(first, mDriver.warmup() + mDriver.frames(), [&](uint32_t frame) {
        session.renderFrame(frame, camera, settings, clearColor, false, false);
        // Inside the frame rather than after it: the sample carries its frame.
        profiler.recordCounter(
            {"intermediate bytes", frame, profiler.nowNs(), double(session.lastFrameReport().intermediateBytes)});
    });
    session.finish();
    const auto summary = summarizeFrames(profiler, first + mDriver.warmup(), mFrameIndex);
    mRecords.push_back(makeRecord(session, view, settings, summary));
    TerrainBenchRecord& r = mRecords.back();
    r.look = look == backend::Look::Plain ? "plain" : "full";
    r.trace = trace;
    mDriver.markRow(std::string(view) + " " + r.mode + (r.metric != "-" ? "/" + r.metric : std::string()) +
                        (mLooks.size() > 1 ? " " + r.look : std::string()),
                    first, rowStartNs);
    log::info(r.device + " " + r.backend + " " + r.view + " " + r.mode + " " + r.metric + ": " +
              std::to_string(r.gpuMsMedian) + " ms, " + std::to_string(r.triangles) + " triangles" +
              (mLooks.size() > 1 ? ", look " + r.look : std::string()));
}

Status TerrainBench::finish() const {
    std::string table = terrainBenchTable(mRecords);
    if (mDriver.comparing()) table += backendComparisonTable(mRecords, mNotes);
    return mDriver.finish(mRecords.size(), terrainBenchJson(mRecords), table);
}

} // namespace

Status runTerrainBenchmark(const Options& options) {
    auto driver = BenchDriver::start(options, terrainPlan());
    if (!driver) return driver.error();
    auto loaded = World::load(options, 1);
    if (!loaded) return loaded.error();
    const TessellationOptions& levels = options.tessellation;
    const bool compare = driver.value().comparing();
    if (compare && levels.maxLevel && *levels.maxLevel > kComparisonMaxLevel)
        return failSetting(setting::kTessMax, " ", level(*levels.maxLevel), ": ",
                           reporterFor(options).name(setting::kBackend),
                           " all compares the backends at the emulated tessellator's levels, 1 to ",
                           level(kComparisonMaxLevel));
    TerrainBench bench(driver.value(), loaded.value()->terrain());
    const float continuous = levels.continuousLevel.value_or(terrain::TessellationSettings{}.continuousLevel);
    if (compare && continuous > kComparisonMaxLevel)
        bench.note("continuous level " + level(continuous) + " runs as " + level(kComparisonMaxLevel) +
                   " on every backend, the emulated tessellator's maximum");
    for (const auto& device : driver.value().devices())
        for (const auto& backend : driver.value().backends())
            if (Status ok = bench.runBackend(device, backend); !ok) return ok;
    return bench.finish();
}

} // namespace tessera::runtime
