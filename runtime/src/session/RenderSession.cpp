#include "session/RenderSessionImpl.h"

#include "session/SessionGpu.h"
#include "session/TerrainDetailTextures.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"

#include <sstream>

namespace tessera::runtime {
namespace {

/// RenderDoc for a capture of Options::renderdocFrame; null, with a
/// warning, when it cannot be loaded. Called before the instance exists:
/// RenderDoc's layer joins only instances created after it is loaded.
std::unique_ptr<gpu::RenderDoc> loadRenderDoc(const Options& options, const Reporter& reporter) {
    if (!options.renderdocFrame) return nullptr;
    auto loaded = gpu::RenderDoc::load(options.renderdocPath);
    if (loaded) return std::move(loaded.value());
    reporter.warning(
        failSetting(setting::kRenderDocFrame, ": ", loaded.error().message, "; rendering without a capture"));
    return nullptr;
}

/// The backend the options ask for. RenderDoc's layer can hide what Tessera
/// needs (Debian 12's RenderDoc 1.24 reports lavapipe as Vulkan 1.2): a
/// capture is not worth failing the run for, so without a device the
/// selection is tried again without the layer.
Result<std::unique_ptr<SelectedBackend>> selectAroundRenderDoc(const Options& options,
                                                                std::unique_ptr<gpu::RenderDoc>& renderDoc,
                                                                const Reporter& reporter) {
    auto selected = selectBackend(options);
    if (selected || !renderDoc) return selected;
    reporter.warning(failSetting(setting::kRenderDocFrame, ": RenderDoc's layer (API ", renderDoc->version(),
                                 ") leaves no device Tessera can use (", reporter.wording(selected.error()),
                                 "); rendering without a capture"));
    renderDoc->disableLayer();
    renderDoc.reset();
    return selectBackend(options);
}

/// What the device lacks degrades a feature rather than failing the run;
/// says so instead of leaving a solid frame or zero timings unexplained
/// (--hide-features can cause both on purpose).
void warnWhatDegrades(const Options& options, const gpu::Device& device, const Reporter& reporter) {
    const auto& f = device.features();
    if (options.wireframe && !f.fillModeNonSolid)
        reporter.warning(failSetting(setting::kWireframe, ": ", f.deviceName,
                                     " has no wireframe fill mode (fillModeNonSolid); drawing solid"));
    if (!f.timestamps && (!options.benchmark.empty() || !options.capture.empty() || !options.bench.empty()))
        log::warning(f.deviceName + " has no timestamp queries on its graphics queue: every GPU time in the "
                     "benchmark and the trace reads 0");
}

} // namespace

RenderSession::RenderSession(std::unique_ptr<Impl> impl) : mImpl(std::move(impl)) {}

Result<std::unique_ptr<RenderSession>> RenderSession::create(const Options& options, terrain::Terrain& terrain) {
    std::unique_ptr<RenderSession> session(new RenderSession(std::make_unique<Impl>()));
    Impl& s = *session->mImpl;
    s.terrain = &terrain;
    s.reporter = &reporterFor(options);
    s.renderDoc = loadRenderDoc(options, *s.reporter);
    auto selected = selectAroundRenderDoc(options, s.renderDoc, *s.reporter);
    if (!selected) return selected.error();
    s.selected = std::move(selected.value());
    log::info("backend " + session->capabilities().name + " on " + session->deviceName());
    // Asked for by name, cascaded shadows are refused where the backend has
    // none; a backend switched to at run time that lacks them draws blobs.
    if (options.shadows == backend::Shadows::Cascaded && !session->capabilities().cascadedShadows)
        return failSetting(setting::kShadows, " cascaded: backend ", session->capabilities().name,
                           " draws no cascaded shadow maps (blob shadows only)");
    if (const gpu::Device* device = s.selected->device.get()) warnWhatDegrades(options, *device, *s.reporter);
    if (s.renderDoc && !s.selected->instance) {
        s.reporter->warning(failSetting(setting::kRenderDocFrame, ": backend ", session->capabilities().name,
                                        " records no GPU work to capture"));
        s.renderDoc.reset();
    }
    if (s.renderDoc) {
        s.captureFrame = options.renderdocFrame;
        log::info("RenderDoc (API " + s.renderDoc->version() + "): capturing frame " +
                  std::to_string(*options.renderdocFrame));
    }
    s.width = options.width.value_or(kDefaultWidth);
    s.height = options.height.value_or(kDefaultHeight);
    s.look = options.look;
    s.terrainShading = options.terrainShading;
    s.shadows = options.shadows;
    s.sunDirection = options.sunDirection;
    if (Status ok = s.openTarget(options.window); !ok) return ok.error();
    // The detail textures are content like the height map: a missing or
    // broken file ends the run with its name rather than a flat terrain.
    // Loaded once: every backend of the session uploads the same.
    auto detail = loadTerrainDetailTextures(options.contentDir);
    if (!detail) return detail.error();
    s.detailTextures = std::move(detail.value());
    if (Status ok = s.initializeBackend(false); !ok) return ok.error();
    return session;
}

Status RenderSession::Impl::openTarget(bool windowed) {
    gpu::Device* device = selected->device.get();
    if (!device) return {};
    if (windowed) {
        auto created = gpu::Swapchain::create(*selected->instance, *device, width, height, "Tessera");
        if (!created) return created.error();
        swapchain = std::move(created.value());
    }
    target = std::make_unique<gpu::RenderTarget>(*device, width, height);
    scheduler = std::make_unique<gpu::FrameScheduler>(*device, profiler::Profiler::global(), *target);
    return {};
}

RenderSession::~RenderSession() {
    mImpl->releaseBackend(Impl::Release::Shutdown);
    for (auto& [name, parked] : mImpl->parked) parked.backend->shutdown();
    mImpl->parked.clear();
}

const backend::BackendCapabilities& RenderSession::capabilities() const { return mImpl->selected->capabilities; }
uint32_t RenderSession::width() const { return mImpl->width; }
uint32_t RenderSession::height() const { return mImpl->height; }
bool RenderSession::windowed() const { return mImpl->swapchain != nullptr; }
void RenderSession::setTerrainVisible(bool visible) { mImpl->terrainVisible = visible; }
void RenderSession::setLook(backend::Look look) { mImpl->look = look; }
backend::Look RenderSession::look() const { return mImpl->look; }
void RenderSession::setParkBackends(bool park) { mImpl->parkBackends = park; }
uint64_t RenderSession::generation() const { return mImpl->generation; }
backend::FrameReport RenderSession::lastFrameReport() const { return mImpl->selected->backend->lastFrameReport(); }
uint32_t RenderSession::lastPatchCount() const { return static_cast<uint32_t>(mImpl->visible.size()); }
const std::filesystem::path& RenderSession::captureFile() const { return mImpl->captureFile; }

void RenderSession::setShadowCasters(std::span<const glm::vec4> casters, const glm::vec3& region) {
    mImpl->shadowCasters = casters;
    mImpl->shadowRegion = region;
}

uint64_t RenderSession::deviceBytes() const {
    const gpu::Device* device = mImpl->selected->device.get();
    return device ? device->allocatedBytes() : 0;
}

uint64_t RenderSession::peakDeviceBytes() const {
    const gpu::Device* device = mImpl->selected->device.get();
    return device ? device->peakAllocatedBytes() : 0;
}

uint64_t RenderSession::deviceAllocations() const {
    const gpu::Device* device = mImpl->selected->device.get();
    return device ? device->allocationCount() : 0;
}

void RenderSession::setDeviceMemoryCap(uint64_t bytes) {
    if (gpu::Device* device = mImpl->selected->device.get()) device->setMemoryCap(bytes);
}

lod::DeviceClass RenderSession::deviceClass() const {
    const gpu::Device* device = mImpl->selected->device.get();
    return device && device->features().isCpu ? lod::DeviceClass::Cpu : lod::DeviceClass::Gpu;
}

std::string RenderSession::deviceName() const {
    const gpu::Device* device = mImpl->selected->device.get();
    return device ? device->features().deviceName : std::string("none (null backend)");
}

std::string RenderSession::driverName() const {
    const gpu::Device* device = mImpl->selected->device.get();
    if (!device) return "none";
    const auto& f = device->features();
    return f.driverName + " " + f.driverInfo;
}
void RenderSession::updateGround(terrain::DrawnSurface& ground, const scene::Camera& camera,
                                 const terrain::TessellationSettings& settings) const {
    // With no terrain drawn (--no-terrain) there is nothing to stand on:
    // the height field, so that terrain-less views stay the same whatever
    // the levels (the backends' character parity and crack tests).
    if (!mImpl->terrainVisible) return ground.useHeightField();
    const auto& caps = capabilities();
    terrain::TessellationSettings drawn = settings;
    if (!caps.drawsTerrainMode(drawn.mode)) drawn.mode = terrain::TerrainMode::LowRes;
    ground.update(drawn, terrain::TessView::fromCamera(camera, height()), caps.maxTessFactor);
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
        auto handle = mImpl->selected->backend->createCharacter({&asset.asset, asset.box});
        if (!handle) return fail(asset.file, ": ", handle.error().message);
        handles.push_back(handle.value());
        mImpl->characters.push_back(handle.value());
    }
    assets.bind(std::move(handles));
    return {};
}

Status RenderSession::createCrowd(const backend::CrowdDesc& desc) {
    TESSERA_CPU_SCOPE("load.crowdUpload");
    auto handle = mImpl->selected->backend->createCrowd(desc);
    if (!handle) return fail("backend ", capabilities().name, ": ", handle.error().message);
    mImpl->crowd = handle.value();
    return {};
}

Status RenderSession::createSubdivs(SubdivSource& models) {
    TESSERA_CPU_SCOPE("load.subdivUpload");
    for (size_t i = 0; i < models.size(); ++i) {
        auto handle = mImpl->selected->backend->createSubdiv(models.desc(i));
        if (!handle) return fail("backend ", capabilities().name, ": ", handle.error().message);
        models.setHandle(i, handle.value());
        mImpl->subdivs.push_back(handle.value());
    }
    return {};
}

Result<backend::SubdivPoints> RenderSession::readSubdivPoints(backend::SubdivHandle handle) {
    return mImpl->selected->backend->readSubdivPoints(handle);
}

Result<backend::CrowdTiers> RenderSession::readCrowdTiers() {
    if (!mImpl->crowd.valid()) return Error{"no instanced crowd on backend " + capabilities().name};
    return mImpl->selected->backend->readCrowdTiers(mImpl->crowd);
}

Result<std::vector<uint16_t>> RenderSession::readHeights() {
    return mImpl->selected->backend->readTerrainHeights(mImpl->terrainHandle);
}

bool RenderSession::pollWindow() {
    gpu::Swapchain* swapchain = mImpl->swapchain.get();
    if (!swapchain) return true;
    if (swapchain->pollEvents()) swapchain->recreate();
    return !swapchain->shouldClose();
}

std::vector<uint8_t> RenderSession::finish() {
    if (!mImpl->scheduler) return {};
    mImpl->scheduler->waitIdle();
    return mImpl->scheduler->readbackPixels();
}

Status RenderSession::requestCapture() {
    if (!mImpl->renderDoc)
        return fail("no RenderDoc capture: start with ", mImpl->reporter->name(setting::kRenderDocFrame),
                    " N (and RenderDoc installed) to capture from the window");
    mImpl->captureFrame = mImpl->frameIndex + 1;
    return {};
}

gpu::Device* SessionGpu::device(const RenderSession& session) { return session.mImpl->selected->device.get(); }

GLFWwindow* SessionGpu::window(const RenderSession& session) {
    return session.mImpl->swapchain ? session.mImpl->swapchain->window() : nullptr;
}

void SessionGpu::setOverlayRecorder(RenderSession& session, std::function<void(gpu::FrameContext&)> recorder) {
    session.mImpl->overlay = std::move(recorder);
}

} // namespace tessera::runtime
