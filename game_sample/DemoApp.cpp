#include "DemoApp.h"

#include "BackendSelection.h"
#include "ContentLocator.h"
#include "tessera/core/ImageFile.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/FrameScheduler.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/gpu/Swapchain.h"
#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/profiler/TraceWriter.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/CameraPath.h"
#include "tessera/scene/SceneGraph.h"
#include "tessera/terrain/HeightMapIO.h"
#include "tessera/terrain/TerrainTiles.h"

#include <cstdio>
#include <optional>

namespace tessera::demo {
namespace {

// The flythrough advances a fixed step per frame, not wall time, so a given
// seed and frame index always give the same picture on any machine.
constexpr double kSecondsPerFrame = 1.0 / 30.0;
constexpr uint32_t kDefaultHeadlessFrames = 60;
constexpr uint32_t kTilesPerSide = 16;
constexpr uint32_t kQuadsPerTile = 32;

/// Everything one run owns, in destruction order (last declared dies first).
struct Session {
    std::unique_ptr<SelectedBackend> selected;
    std::optional<terrain::HeightField> heights;
    scene::SceneGraph scene;
    std::optional<terrain::TerrainTiles> tiles;
    std::unique_ptr<gpu::Swapchain> swapchain;
    std::unique_ptr<gpu::RenderTarget> target;
    std::unique_ptr<gpu::FrameScheduler> scheduler;
    backend::TerrainHandle terrain;
};

Status loadTerrain(const DemoOptions& options, Session& s) {
    TESSERA_CPU_SCOPE("load.terrain");
    std::filesystem::path path = options.heightmap;
    if (path.empty()) {
        auto located = locateContent(options.contentDir, "terrain/height.png");
        if (!located) return located.error();
        path = located.value();
    }
    auto field = terrain::loadHeightMapPng(path);
    if (!field) return field.error();
    s.heights.emplace(std::move(field.value()));
    s.tiles.emplace(s.scene, *s.heights, kTilesPerSide);
    return {};
}

Status setUpGpu(const DemoOptions& options, Session& s, uint32_t& width, uint32_t& height) {
    gpu::Device* device = s.selected->device.get();
    if (!device) return {};
    if (options.window) {
        auto swapchain = gpu::Swapchain::create(*s.selected->instance, *device, width, height, "Tessera");
        if (!swapchain) return swapchain.error();
        s.swapchain = std::move(swapchain.value());
    }
    s.target = std::make_unique<gpu::RenderTarget>(*device, width, height);
    s.scheduler = std::make_unique<gpu::FrameScheduler>(*device, profiler::Profiler::global(), *s.target);
    return {};
}

Status writeOutputs(const DemoOptions& options, Session& s, const std::vector<uint8_t>& pixels, uint32_t width,
                    uint32_t height, uint32_t frames) {
    auto& profiler = profiler::Profiler::global();
    const backend::DeviceFeatures* features = s.selected->device ? &s.selected->device->features() : nullptr;
    const std::string deviceName = features ? features->deviceName : "none (null backend)";
    const std::string driver = features ? features->driverName + " " + features->driverInfo : "none";
    if (!options.screenshot.empty()) {
        if (pixels.empty()) return fail("--screenshot ", options.screenshot, ": the ", s.selected->capabilities.name,
                                        " backend renders no pixels");
        if (auto w = writePng(options.screenshot, {width, height, pixels}); !w) return w;
        log::info("wrote " + options.screenshot);
    }
    if (!options.capture.empty()) {
        profiler::TraceMetadata meta;
        meta.backend = s.selected->capabilities.name;
        meta.device = deviceName;
        meta.driver = driver;
        meta.width = width;
        meta.height = height;
        if (auto w = profiler::writeChromeTrace(profiler, options.capture, meta); !w) return w;
        log::info("wrote " + options.capture);
    }
    if (!options.benchmark.empty()) {
        profiler.discardFramesBefore(options.warmup);
        auto summary = profiler::summarize(profiler);
        profiler::BenchmarkInfo info;
        info.backend = s.selected->capabilities.name;
        info.device = deviceName;
        info.driver = driver;
        info.scene = "terrain";
        info.width = width;
        info.height = height;
        info.warmupFrames = options.warmup;
        info.frames = frames > options.warmup ? frames - options.warmup : 0;
        if (auto w = profiler::writeBenchmarkJson(summary, info, profiler, options.benchmark); !w) return w;
        std::printf("%s", profiler::formatTable(summary).c_str());
        log::info("wrote " + options.benchmark);
    }
    return {};
}

Status run(const DemoOptions& options, Session& s) {
    auto& profiler = profiler::Profiler::global();
    profiler.setEnabled(!options.capture.empty() || !options.benchmark.empty());

    auto selected = selectBackend(options);
    if (!selected) return selected.error();
    s.selected = std::move(selected.value());
    backend::Backend& backend = *s.selected->backend;
    log::info("backend " + s.selected->capabilities.name + " on " +
              (s.selected->device ? s.selected->device->features().deviceName : std::string("no device")));

    if (auto loaded = loadTerrain(options, s); !loaded) return loaded;
    uint32_t width = options.width, height = options.height;
    if (auto gpu = setUpGpu(options, s, width, height); !gpu) return gpu;

    backend::BackendInitInfo init;
    init.device = s.selected->device.get();
    if (init.device) init.features = init.device->features();
    init.colorFormat = static_cast<uint32_t>(gpu::RenderTarget::kColorFormat);
    init.depthFormat = static_cast<uint32_t>(gpu::RenderTarget::kDepthFormat);
    if (auto ok = backend.initialize(init); !ok) return ok;
    auto terrain = backend.createTerrain({&*s.heights, kTilesPerSide, kQuadsPerTile});
    if (!terrain) return terrain.error();
    s.terrain = terrain.value();

    scene::CameraPathSettings pathSettings;
    pathSettings.seed = options.seed;
    pathSettings.regionMin = glm::vec2(0.0f);
    pathSettings.regionMax = s.heights->worldSize();
    pathSettings.clearance = 120.0f;
    const terrain::HeightField& field = *s.heights;
    scene::CameraPath path(pathSettings, [&](float x, float z) { return field.heightAt(x, z); });
    scene::Camera camera;

    const bool windowed = s.swapchain != nullptr;
    // --warmup frames run first and are discarded from the benchmark; --frames
    // counts the frames after them.
    const uint32_t measured =
        options.frames ? options.frames : (windowed ? UINT32_MAX - options.warmup : kDefaultHeadlessFrames);
    const uint32_t frames = options.warmup + measured;
    std::vector<uint32_t> visible;
    std::vector<uint8_t> pixels;
    uint32_t rendered = 0;
    for (uint32_t frame = 0; frame < frames; ++frame, ++rendered) {
        if (windowed) {
            if (s.swapchain->pollEvents()) s.swapchain->recreate();
            if (s.swapchain->shouldClose()) break;
        }
        profiler.beginFrame(frame);
        {
            TESSERA_CPU_SCOPE("camera.update");
            camera.setPose(options.camera ? *options.camera : path.sample(frame * kSecondsPerFrame));
            camera.setAspect(float(width) / float(height));
        }
        visible.clear();
        {
            TESSERA_CPU_SCOPE("terrain.cull");
            s.tiles->cull(camera.frustum(), camera.position(), visible);
        }
        backend::FrameInfo info;
        info.frameIndex = frame;
        info.timeSeconds = frame * kSecondsPerFrame;
        info.view = camera.view();
        info.projection = camera.projection();
        info.viewProjection = camera.viewProjection();
        info.cameraPosition = camera.position();
        info.clearColor = glm::vec4(options.clearColor, 1.0f);
        info.width = width;
        info.height = height;
        info.wireframe = options.wireframe;
        {
            TESSERA_CPU_SCOPE("render.record");
            if (s.scheduler) info.gpu = &s.scheduler->beginFrame(frame);
            backend.beginFrame(info);
            backend.drawTerrain(s.terrain, {visible, backend::TerrainMode::LowRes});
            backend.endFrame();
        }
        const bool last = frame + 1 == frames;
        if (s.scheduler) {
            TESSERA_CPU_SCOPE("render.submit");
            s.scheduler->endFrame(last && !options.screenshot.empty(), s.swapchain.get());
        }
        const auto report = backend.lastFrameReport();
        profiler.recordCounter({"tiles drawn", uint64_t(frame), profiler.nowNs(), double(report.terrainTilesDrawn)});
        profiler.recordCounter({"triangles submitted", uint64_t(frame), profiler.nowNs(), double(report.trianglesSubmitted)});
        profiler.endFrame();
    }
    if (s.scheduler) {
        s.scheduler->waitIdle();
        pixels = s.scheduler->readbackPixels();
    }
    backend.destroyTerrain(s.terrain);
    backend.shutdown();
    return writeOutputs(options, s, pixels, width, height, rendered);
}

} // namespace

int runDemo(const DemoOptions& options) {
    if (options.listDevices || options.listBackends) {
        Status listed = options.listDevices ? listDevices(options) : listBackends(options);
        if (!listed) {
            log::error(listed.error().message);
            return 1;
        }
        return 0;
    }
    int code = 0;
    {
        Session session;
        if (auto ran = run(options, session); !ran) {
            log::error(ran.error().message);
            code = 1;
        }
    }
    if (options.validation) {
        // Printed after every Vulkan object is gone, so messages from
        // destruction are counted too.
        const uint64_t messages = gpu::Instance::validationMessageCount();
        std::printf("validation messages: %llu\n", static_cast<unsigned long long>(messages));
        if (messages > 0 && code == 0) code = 1;
    }
    return code;
}

} // namespace tessera::demo
