#include "SubdivTestHost.h"

#include "tessera/backend/PluginLoader.h"
#include "tessera/profiler/Profiler.h"

namespace tessera::test {

Result<std::unique_ptr<SubdivTestHost>> SubdivTestHost::create(gpu::Device& device, const std::string& name,
                                                               uint32_t width, uint32_t height) {
    std::unique_ptr<SubdivTestHost> host(new SubdivTestHost());
    backend::PluginLoader loader;
    loader.addSearchDirectory(TESSERA_PLUGIN_DIR);
    if (Status loaded = loader.loadBackend(name, host->mRegistry); !loaded) return loaded.error();
    auto created = host->mRegistry.create(name);
    if (!created) return created.error();
    host->mBackend = std::move(created.value());
    const backend::BackendCapabilities caps = host->mBackend->capabilities(&device.features());
    if (!caps.supported()) return fail("backend ", name, " cannot run on ", device.features().deviceName);
    if (!caps.subdiv) return fail("backend ", name, " draws no subdivision surfaces");
    host->mTarget = std::make_unique<gpu::RenderTarget>(device, width, height);
    host->mScheduler = std::make_unique<gpu::FrameScheduler>(device, profiler::Profiler::global(), *host->mTarget);
    backend::BackendInitInfo init;
    init.device = &device;
    init.features = device.features();
    init.colorFormat = static_cast<uint32_t>(gpu::RenderTarget::kColorFormat);
    init.depthFormat = static_cast<uint32_t>(gpu::RenderTarget::kDepthFormat);
    if (Status ok = host->mBackend->initialize(init); !ok) return ok.error();
    return host;
}

SubdivTestHost::~SubdivTestHost() {
    if (mScheduler) mScheduler->waitIdle();
    if (mBackend) mBackend->shutdown();
}

std::vector<uint8_t> SubdivTestHost::drawFrame(
    const scene::Camera& camera, std::span<const std::pair<backend::SubdivHandle, backend::SubdivDrawInfo>> draws,
    bool wireframe) {
    backend::FrameInfo info;
    info.frameIndex = mFrame;
    info.view = camera.view();
    info.projection = camera.projection();
    info.viewProjection = camera.viewProjection();
    info.cameraPosition = camera.position();
    info.width = width();
    info.height = height();
    info.wireframe = wireframe;
    info.gpu = &mScheduler->beginFrame(mFrame++);
    mBackend->beginFrame(info);
    for (const auto& [handle, draw] : draws) mBackend->drawSubdiv(handle, draw);
    mBackend->endFrame();
    mScheduler->endFrame(true);
    mScheduler->waitIdle();
    return mScheduler->readbackPixels();
}

} // namespace tessera::test
