#include "tessera/runtime/RenderSession.h"

#include "TerrainDetailTextures.h"

#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/runtime/World.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"

#include <chrono>
#include <cstdio>
#include <sstream>

namespace tessera::runtime {

Result<std::unique_ptr<RenderSession>> RenderSession::create(const Options& options, terrain::Terrain& terrain) {
    std::unique_ptr<RenderSession> session(new RenderSession());
    session->mTerrain = &terrain;
    session->mReporter = &reporterFor(options);
    const Reporter& reporter = *session->mReporter;
    // Before the instance exists: RenderDoc's layer joins only instances
    // created after it is loaded.
    if (options.renderdocFrame) {
        auto loaded = gpu::RenderDoc::load(options.renderdocPath);
        if (!loaded)
            reporter.warning(failSetting(setting::kRenderDocFrame, ": ", loaded.error().message,
                                         "; rendering without a capture"));
        else session->mRenderDoc = std::move(loaded.value());
    }
    auto selected = selectBackend(options);
    if (!selected && session->mRenderDoc) {
        // RenderDoc's layer can hide what Tessera needs (Debian 12's RenderDoc
        // 1.24 reports lavapipe as Vulkan 1.2): a capture is not worth failing
        // the run for, so try again without the layer.
        reporter.warning(failSetting(setting::kRenderDocFrame, ": RenderDoc's layer (API ",
                                     session->mRenderDoc->version(), ") leaves no device Tessera can use (",
                                     reporter.wording(selected.error()), "); rendering without a capture"));
        session->mRenderDoc->disableLayer();
        session->mRenderDoc.reset();
        selected = selectBackend(options);
    }
    if (!selected) return selected.error();
    session->mSelected = std::move(selected.value());
    log::info("backend " + session->capabilities().name + " on " + session->deviceName());
    if (const gpu::Device* device = session->mSelected->device.get()) {
        // What the device lacks degrades a feature rather than failing the
        // run; say so instead of leaving a solid frame or zero timings
        // unexplained (--hide-features can cause both on purpose).
        const auto& f = device->features();
        if (options.wireframe && !f.fillModeNonSolid)
            reporter.warning(failSetting(setting::kWireframe, ": ", f.deviceName,
                                         " has no wireframe fill mode (fillModeNonSolid); drawing solid"));
        if (!f.timestamps && (!options.benchmark.empty() || !options.capture.empty() || !options.bench.empty()))
            log::warning(f.deviceName + " has no timestamp queries on its graphics queue: every GPU time in the "
                         "benchmark and the trace reads 0");
    }
    if (session->mRenderDoc && !session->mSelected->instance) {
        reporter.warning(failSetting(setting::kRenderDocFrame, ": backend ", session->capabilities().name,
                                     " records no GPU work to capture"));
        session->mRenderDoc.reset();
    }
    if (session->mRenderDoc) {
        session->mCaptureFrame = options.renderdocFrame;
        log::info("RenderDoc (API " + session->mRenderDoc->version() + "): capturing frame " +
                  std::to_string(*options.renderdocFrame));
    }

    session->mWidth = options.width.value_or(kDefaultWidth);
    session->mLook = options.look;
    session->mTerrainShading = options.terrainShading;
    session->mSunDirection = options.sunDirection;
    session->mHeight = options.height.value_or(kDefaultHeight);
    gpu::Device* device = session->mSelected->device.get();
    if (device) {
        if (options.window) {
            auto swapchain = gpu::Swapchain::create(*session->mSelected->instance, *device, session->mWidth,
                                                    session->mHeight, "Tessera");
            if (!swapchain) return swapchain.error();
            session->mSwapchain = std::move(swapchain.value());
        }
        session->mTarget = std::make_unique<gpu::RenderTarget>(*device, session->mWidth, session->mHeight);
        session->mScheduler =
            std::make_unique<gpu::FrameScheduler>(*device, profiler::Profiler::global(), *session->mTarget);
    }

    // The detail textures are content like the height map: a missing or
    // broken file ends the run with its name rather than a flat terrain.
    // Loaded once: every backend of the session uploads the same.
    auto detail = loadTerrainDetailTextures(options.contentDir);
    if (!detail) return detail.error();
    session->mDetailTextures = std::move(detail.value());
    if (Status ok = session->initializeBackend(false); !ok) return ok.error();
    return session;
}

Status RenderSession::initializeBackend(bool alreadyInitialized) {
    backend::Backend& backend = *mSelected->backend;
    ++mGeneration;
    if (!alreadyInitialized) {
        gpu::Device* device = mSelected->device.get();
        backend::BackendInitInfo init;
        init.device = device;
        if (device) init.features = device->features();
        init.colorFormat = static_cast<uint32_t>(gpu::RenderTarget::kColorFormat);
        init.depthFormat = static_cast<uint32_t>(gpu::RenderTarget::kDepthFormat);
        if (auto ok = backend.initialize(init); !ok) {
            // What initialize made before it failed is released now, not
            // when the backend object goes (the contract: shutdown releases
            // whatever initialize made; a failed switch drops the object).
            backend.shutdown();
            return ok.error();
        }
    }
    // The upload copies the CPU height field as it is now, craters included,
    // so the splats still queued (--splat) must not be applied a second time.
    (void)mTerrain->takePendingSplats();
    backend::TerrainDesc desc;
    desc.terrain = mTerrain;
    desc.detailTextures = mDetailTextures;
    auto handle = backend.createTerrain(desc);
    if (!handle) {
        backend.shutdown();
        return handle.error();
    }
    mTerrainHandle = handle.value();
    return {};
}

void RenderSession::releaseBackend(Release release) {
    if (!mSelected || !mSelected->backend) return;
    if (mScheduler) mScheduler->waitIdle();
    backend::Backend& backend = *mSelected->backend;
    for (backend::CharacterHandle character : mCharacters) backend.destroyCharacter(character);
    for (backend::SubdivHandle surface : mSubdivs) backend.destroySubdiv(surface);
    if (mCrowd.valid()) backend.destroyCrowd(mCrowd);
    if (mTerrainHandle.valid()) backend.destroyTerrain(mTerrainHandle);
    mCharacters.clear();
    mSubdivs.clear();
    mCrowd = {};
    mTerrainHandle = {};
    if (release == Release::Park && mParkBackends) {
        // Kept initialised, with no scene objects, for a switch back: its
        // pipelines are what a switch spends its time on (seconds on a
        // software rasterizer).
        const std::string name = mSelected->capabilities.name;
        mParked[name] = {std::move(mSelected->backend), mSelected->capabilities};
    } else if (release != Release::Keep) {
        backend.shutdown();
    }
    // Deferred destructions wait for frames in flight; there are none now.
    if (mScheduler) mScheduler->waitIdle();
}

Status RenderSession::requestCapture() {
    if (!mRenderDoc)
        return fail("no RenderDoc capture: start with ", mReporter->name(setting::kRenderDocFrame),
                    " N (and RenderDoc installed) to capture from the window");
    mCaptureFrame = mFrameIndex + 1;
    return {};
}

Status RenderSession::switchBackend(const Options& options, const std::string& name, terrain::Terrain* terrain) {
    TESSERA_CPU_SCOPE("session.switchBackend");
    const auto start = std::chrono::steady_clock::now();
    const std::string previous = capabilities().name;
    ParkedBackend next;
    bool warm = false;
    if (name == previous && mParkBackends) {
        // The same backend again (a world loaded anew): keep it, re-create
        // the scene on it.
        releaseBackend(Release::Keep);
        if (terrain) mTerrain = terrain;
        return initializeBackend(true);
    }
    if (auto it = mParked.find(name); it != mParked.end()) {
        next = std::move(it->second);
        mParked.erase(it);
        warm = true;
    } else {
        auto created = createBackendOnDevice(*mSelected, options, name, next.capabilities);
        if (!created) return created.error();
        next.backend = std::move(created.value());
    }
    releaseBackend(Release::Park);
    if (terrain) mTerrain = terrain;
    mSelected->backend = std::move(next.backend);
    mSelected->capabilities = next.capabilities;
    Status ok = initializeBackend(warm);
    if (ok) {
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        log::info("switched backend " + previous + " -> " + name + " on " + deviceName() + " (" +
                  std::to_string(int(ms)) + " ms" + (warm ? ", kept from before" : "") + "; the scene uploads follow)");
        return {};
    }
    // Leave the session drawing as before rather than with no backend.
    mSelected->backend.reset();
    ParkedBackend back;
    bool backWarm = false;
    if (auto it = mParked.find(previous); it != mParked.end()) {
        back = std::move(it->second);
        mParked.erase(it);
        backWarm = true;
    } else if (auto created = createBackendOnDevice(*mSelected, options, previous, back.capabilities); created) {
        back.backend = std::move(created.value());
    }
    if (back.backend) {
        mSelected->backend = std::move(back.backend);
        mSelected->capabilities = back.capabilities;
        if (Status again = initializeBackend(backWarm); !again)
            log::error("backend " + previous + ": " + again.error().message);
    }
    return fail("switching to backend ", name, ": ", ok.error().message);
}

RenderSession::~RenderSession() {
    releaseBackend(Release::Shutdown);
    for (auto& [name, parked] : mParked) parked.backend->shutdown();
    mParked.clear();
}

lod::DeviceClass RenderSession::deviceClass() const {
    return mSelected->device && mSelected->device->features().isCpu ? lod::DeviceClass::Cpu : lod::DeviceClass::Gpu;
}

std::string RenderSession::deviceName() const {
    return mSelected->device ? mSelected->device->features().deviceName : std::string("none (null backend)");
}

std::string RenderSession::driverName() const {
    if (!mSelected->device) return "none";
    const auto& f = mSelected->device->features();
    return f.driverName + " " + f.driverInfo;
}

Result<terrain::TessellationSettings> RenderSession::resolveTessellation(const Options& options) const {
    const auto& caps = capabilities();
    const TessellationOptions& asked = options.tessellation;
    terrain::TessellationSettings settings = asked.settings();
    if (options.terrainMode) {
        settings.mode = *options.terrainMode;
        if (!caps.drawsTerrainMode(settings.mode)) {
            std::ostringstream modes;
            for (auto m : {terrain::TerrainMode::LowRes, terrain::TerrainMode::Continuous, terrain::TerrainMode::Adaptive})
                if (caps.drawsTerrainMode(m)) modes << (modes.tellp() > 0 ? ", " : "") << terrain::toString(m);
            return failSetting(setting::kTerrainMode, " ", terrain::toString(settings.mode), ": backend ", caps.name,
                        " does not draw it (it draws: ", modes.str(), ")");
        }
    } else {
        settings.mode = caps.drawsTerrainMode(terrain::TerrainMode::Adaptive) ? terrain::TerrainMode::Adaptive
                                                                               : terrain::TerrainMode::LowRes;
    }
    if (settings.mode == terrain::TerrainMode::LowRes) return settings;
    // A level the user asked for and the backend cannot draw is an error;
    // the defaults (64, 15) are clamped to the backend's maximum instead, as
    // D3D10-era hardware clamps to 14.99.
    const std::string top = formatNumber(caps.maxTessFactor);
    if (asked.maxLevel && settings.maxLevel > caps.maxTessFactor)
        return failSetting(setting::kTessMax, " ", formatNumber(settings.maxLevel), ": backend ", caps.name,
                           " tessellates up to level ", top);
    if (settings.mode == terrain::TerrainMode::Continuous && asked.continuousLevel &&
        settings.continuousLevel > caps.maxTessFactor)
        return failSetting(setting::kTessLevel, " ", formatNumber(settings.continuousLevel), ": backend ", caps.name,
                    " tessellates up to level ", top);
    settings.maxLevel = std::min(settings.maxLevel, caps.maxTessFactor);
    settings.continuousLevel = std::min(settings.continuousLevel, caps.maxTessFactor);
    return settings;
}

Status RenderSession::createCharacters(CharacterAssets& assets) {
    TESSERA_CPU_SCOPE("load.characterUpload");
    std::vector<backend::CharacterHandle> handles;
    for (const CrowdAsset& asset : assets.all()) {
        auto handle = mSelected->backend->createCharacter({&asset.asset, asset.box});
        if (!handle) return fail(asset.file, ": ", handle.error().message);
        handles.push_back(handle.value());
        mCharacters.push_back(handle.value());
    }
    assets.bind(std::move(handles));
    return {};
}

Status RenderSession::createCrowd(const backend::CrowdDesc& desc) {
    TESSERA_CPU_SCOPE("load.crowdUpload");
    auto handle = mSelected->backend->createCrowd(desc);
    if (!handle) return fail("backend ", capabilities().name, ": ", handle.error().message);
    mCrowd = handle.value();
    return {};
}

Status RenderSession::createSubdivs(SubdivSource& models) {
    TESSERA_CPU_SCOPE("load.subdivUpload");
    for (size_t i = 0; i < models.size(); ++i) {
        auto handle = mSelected->backend->createSubdiv(models.desc(i));
        if (!handle) return fail("backend ", capabilities().name, ": ", handle.error().message);
        models.setHandle(i, handle.value());
        mSubdivs.push_back(handle.value());
    }
    return {};
}

Result<backend::SubdivPoints> RenderSession::readSubdivPoints(backend::SubdivHandle handle) {
    return mSelected->backend->readSubdivPoints(handle);
}

Result<backend::CrowdTiers> RenderSession::readCrowdTiers() {
    if (!mCrowd.valid()) return Error{"no instanced crowd on backend " + capabilities().name};
    return mSelected->backend->readCrowdTiers(mCrowd);
}

bool RenderSession::pollWindow() {
    if (!mSwapchain) return true;
    if (mSwapchain->pollEvents()) mSwapchain->recreate();
    return !mSwapchain->shouldClose();
}

void RenderSession::renderFrame(uint32_t frameIndex, const scene::Camera& camera,
                                const terrain::TessellationSettings& settings, const glm::vec3& clearColor,
                                bool wireframe, bool readback, const backend::CharacterDrawInfo* characters,
                                const backend::CrowdDrawInfo* crowd, std::span<const SubdivDraw> surfaces) {
    backend::Backend& backend = *mSelected->backend;
    mFrameIndex = frameIndex;
    mVisible.clear();
    {
        TESSERA_CPU_SCOPE("terrain.cull");
        if (mTerrainVisible) mTerrain->cull(camera.frustum(), camera.position(), mVisible);
    }
    const std::vector<terrain::CraterSplat> splats = mTerrain->takePendingSplats();
    backend::FrameInfo info;
    info.frameIndex = frameIndex;
    info.timeSeconds = frameIndex * World::kSecondsPerFrame;
    info.view = camera.view();
    info.projection = camera.projection();
    info.viewProjection = camera.viewProjection();
    info.cameraPosition = camera.position();
    info.clearColor = glm::vec4(clearColor, 1.0f);
    info.width = mWidth;
    info.height = mHeight;
    info.wireframe = wireframe;
    if (mTerrainVisible) {
        info.shadowCasters = mShadowCasters;
        info.shadowRegion = mShadowRegion;
    }
    info.look = mLook;
    info.terrainShading = mTerrainShading;
    info.sunDirection = mSunDirection;
    const bool capture = mRenderDoc && mCaptureFrame == frameIndex;
    if (capture) mRenderDoc->begin(*mSelected->instance);
    {
        TESSERA_CPU_SCOPE("render.record");
        if (mScheduler) info.gpu = &mScheduler->beginFrame(frameIndex);
        backend.beginFrame(info);
        backend.splatTerrain(mTerrainHandle, splats);
        if (mTerrainVisible) backend.drawTerrain(mTerrainHandle, {mVisible, settings});
        if (characters) backend.drawCharacters(*characters);
        if (crowd && mCrowd.valid()) backend.drawCrowd(mCrowd, *crowd);
        for (const SubdivDraw& surface : surfaces) {
            if (!surface.tileRects.empty()) backend.updateSubdivTiles(surface.handle, surface.tiles, surface.tileRects);
            backend.drawSubdiv(surface.handle, surface.info);
        }
        backend.endFrame();
        if (mOverlay && info.gpu) mOverlay(*info.gpu);
    }
    if (mScheduler) {
        TESSERA_CPU_SCOPE("render.submit");
        mScheduler->endFrame(readback, mSwapchain.get());
    }
    if (capture) {
        auto file = mRenderDoc->end(*mSelected->instance);
        if (!file) mReporter->warning(failSetting(setting::kRenderDocFrame, ": ", file.error().message));
        else {
            mCaptureFile = file.value();
            log::info("RenderDoc capture of frame " + std::to_string(frameIndex) + ": " + mCaptureFile.string());
        }
    }
    auto& profiler = profiler::Profiler::global();
    const backend::FrameReport report = backend.lastFrameReport();
    profiler.recordCounter({"patches drawn", uint64_t(frameIndex), profiler.nowNs(), double(report.terrainPatchesDrawn)});
    profiler.recordCounter({"craters splatted", uint64_t(frameIndex), profiler.nowNs(), double(report.splatsApplied)});
    if (characters)
        profiler.recordCounter({"character triangles", uint64_t(frameIndex), profiler.nowNs(),
                                double(report.characterTriangles)});
    if (crowd) {
        // The GPU's own counts (a backend reads them back a few frames late).
        static const char* const kTierCounters[3] = {"crowd near instances", "crowd middle instances",
                                                     "crowd far instances"};
        for (int t = 0; t < 3; ++t)
            profiler.recordCounter({kTierCounters[t], uint64_t(frameIndex), profiler.nowNs(),
                                    double(report.crowdInstances[t])});
    }
}

std::vector<uint8_t> RenderSession::finish() {
    if (!mScheduler) return {};
    mScheduler->waitIdle();
    return mScheduler->readbackPixels();
}

Result<std::vector<uint16_t>> RenderSession::readHeights() {
    return mSelected->backend->readTerrainHeights(mTerrainHandle);
}

} // namespace tessera::runtime
