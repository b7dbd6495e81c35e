#include "tessera/runtime/Runner.h"

#include "tessera/runtime/BackendSelection.h"
#include "bench/CharacterBenchmark.h"
#include "bench/CrowdBenchmark.h"
#include "bench/CrowdRenderBenchmark.h"
#include "bench/SubdivBenchmark.h"
#include "tessera/runtime/Outputs.h"
#include "tessera/runtime/World.h"
#include "tessera/runtime/InstancedCrowd.h"
#include "characters/LodSettings.h"
#include "tessera/runtime/RenderSession.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/runtime/SceneRun.h"
#include "bench/TerrainBenchmark.h"
#include "window/WindowController.h"
#include "tessera/core/ImageFile.h"
#include "tessera/core/Log.h"
#include "tessera/core/OutOfDeviceMemory.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace tessera::runtime {
namespace {

constexpr uint32_t kDefaultHeadlessFrames = 60;

Status runFlythrough(const Options& options) {
    auto& profiler = profiler::Profiler::global();
    // A window's overlay shows per-pass GPU times, so it profiles too.
    profiler.setEnabled(!options.capture.empty() || !options.benchmark.empty() || options.overlay.value_or(options.window));

    // --warmup frames run first and are discarded from the benchmark; --frames
    // counts the frames after them.
    const uint32_t warmup = options.warmup.value_or(0);
    const uint32_t measured =
        options.frames ? options.frames : (options.window ? UINT32_MAX - warmup : kDefaultHeadlessFrames);
    const uint32_t frames = warmup + measured;
    auto created = SceneRun::create(options, frames);
    if (!created) return created.error();
    SceneRun& run = *created.value();
    World& scene = run.world();
    RenderSession& session = run.session();
    InstancedCrowd* instanced = run.instancedCrowd();
    if (instanced) instanced->keepLists(!options.crowdTiers.empty());

    if (!options.record.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(options.record, ec);
        if (ec) return failSetting(setting::kRecord, " ", options.record, ": ", ec.message());
    }
    // --window: the overlay, the free camera and the controls (--no-overlay
    // keeps the plain window).
    std::unique_ptr<WindowController> window;
    if (options.overlay.value_or(session.windowed())) {
        auto controller = WindowController::create(run, options);
        if (!controller) return controller.error();
        window = std::move(controller.value());
    }
    uint32_t rendered = 0;
    for (uint32_t frame = 0; frame < frames; ++frame, ++rendered) {
        const bool record = !options.record.empty();
        if (window) window->beforeFrame(frame);
        const bool shot = window && window->wantsReadback();
        if (!run.step(frame, shot || record || (frame + 1 == frames && !options.screenshot.empty()))) break;
        if (window) window->afterFrame(frame);
        if (record) {
            // Waits for the frame: a recording is for looking at, not timing.
            char name[32];
            std::snprintf(name, sizeof name, "frame_%04u.png", frame);
            const std::filesystem::path path = std::filesystem::path(options.record) / name;
            if (Status ok = writePng(path, {session.width(), session.height(), session.finish()}); !ok) return ok;
        }
    }
    window.reset();
    const std::vector<uint8_t> pixels = session.finish();
    if (options.renderdocFrame && *options.renderdocFrame >= rendered)
        reporterFor(options).warning(failSetting(setting::kRenderDocFrame, " ", std::to_string(*options.renderdocFrame),
                                                 ": the run ended after ", std::to_string(rendered),
                                                 " frames, so nothing was captured"));
    if (!options.crowdTiers.empty()) {
        if (!instanced)
            return failSetting(setting::kCrowdTiers, ": backend ", session.capabilities().name,
                               " draws no instanced crowd here (it needs ", reporterFor(options).name(setting::kScene),
                               " crowd)");
        auto tiers = session.readCrowdTiers();
        if (!tiers) return tiers.error();
        if (Status ok = instanced->writeTiers(options.crowdTiers, session.capabilities().name, tiers.value()); !ok)
            return ok.error();
        log::info("wrote " + options.crowdTiers);
    }
    if (options.meteors) log::info(std::to_string(scene.impactsLanded()) + " meteor impacts landed");
    if (const SimulatedCrowd* crowd = scene.simulatedCrowd()) std::printf("%s\n", crowd->summary().c_str());
    return writeOutputs(options, session, scene.terrain(), pixels, rendered);
}

/// The run `options` ask for: the flythrough or a benchmark.
Status run(const Options& options) {
    return options.bench.empty()           ? runFlythrough(options)
           : options.bench == "characters" ? runCharacterBenchmark(options)
           : options.bench == "crowd-sim"  ? runCrowdBenchmark(options)
           : options.bench == "crowd"      ? runCrowdRenderBenchmark(options)
           : options.bench == "subdiv"     ? runSubdivBenchmark(options)
                                           : runTerrainBenchmark(options);
}

/// What ran out, and what the caller can ask for instead, naming the
/// settings as `reporter` does.
Error outOfDeviceMemory(const OutOfDeviceMemory& e, const Reporter& reporter) {
    auto name = [&reporter](const char* words) { return reporter.name(words); };
    const std::string less = "ask for less (" + name(setting::kAgents) + ", " + name(setting::kFrameSize) + ", " +
                             name(setting::kModels) + ", a smaller " + name(setting::kHeightMap) + ")";
    return fail(e.what(), "; ",
                e.capBytes() ? "raise it (" + name(setting::kDeviceMemoryCap) + ") or " + less
                             : less + " or pick another " + name(setting::kDevice));
}

} // namespace

int execute(const Options& options) {
    const Reporter& reporter = reporterFor(options);
    if (options.listDevices || options.listBackends) {
        Status listed = options.listDevices ? listDevices(options) : listBackends(options);
        if (!listed) reporter.error(listed.error());
        return listed ? 0 : 1;
    }
    int code = 0;
    try {
        if (Status ran = run(options); !ran) {
            reporter.error(ran.error());
            code = 1;
        }
    } catch (const OutOfDeviceMemory& e) {
        // Thrown by whichever allocation did not fit, at load time or in a
        // frame; by the time it lands here the run's objects have released
        // their GPU resources and the device is gone (core/OutOfDeviceMemory.h).
        reporter.error(outOfDeviceMemory(e, reporter));
        code = 1;
    }
    if (options.validation) {
        // Printed after every Vulkan object is gone, so messages from
        // destruction are counted too.
        const uint64_t messages = validationMessages();
        // On stderr, so stdout stays clean JSON for `--bench terrain` without --out.
        std::fprintf(stderr, "validation messages: %llu\n", static_cast<unsigned long long>(messages));
        if (messages > 0 && code == 0) code = 1;
    }
    return code;
}

} // namespace tessera::runtime
