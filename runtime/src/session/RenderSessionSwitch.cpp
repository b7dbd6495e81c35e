// RenderSession: initialising, releasing and switching its backend (the
// rest of the class is in RenderSession.cpp and RenderSessionFrame.cpp).
#include "session/RenderSessionImpl.h"

#include "tessera/runtime/Reporter.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"

#include <chrono>

namespace tessera::runtime {

Status RenderSession::Impl::initializeBackend(bool alreadyInitialized) {
    backend::Backend& current = *selected->backend;
    ++generation;
    if (!alreadyInitialized) {
        gpu::Device* device = selected->device.get();
        backend::BackendInitInfo init;
        init.device = device;
        if (device) init.features = device->features();
        init.colorFormat = static_cast<uint32_t>(gpu::RenderTarget::kColorFormat);
        init.depthFormat = static_cast<uint32_t>(gpu::RenderTarget::kDepthFormat);
        if (auto ok = current.initialize(init); !ok) {
            // What initialize made before it failed is released now, not
            // when the backend object goes (the contract: shutdown releases
            // whatever initialize made; a failed switch drops the object).
            current.shutdown();
            return ok.error();
        }
    }
    // The upload copies the CPU height field as it is now, craters included,
    // so the splats still queued (--splat) must not be applied a second time.
    (void)terrain->takePendingSplats();
    backend::TerrainDesc desc;
    desc.terrain = terrain;
    desc.detailTextures = detailTextures;
    auto handle = current.createTerrain(desc);
    if (!handle) {
        current.shutdown();
        return handle.error();
    }
    terrainHandle = handle.value();
    return {};
}

void RenderSession::Impl::releaseBackend(Release release) {
    if (!selected || !selected->backend) return;
    if (scheduler) scheduler->waitIdle();
    backend::Backend& current = *selected->backend;
    for (backend::CharacterHandle character : characters) current.destroyCharacter(character);
    for (backend::SubdivHandle surface : subdivs) current.destroySubdiv(surface);
    if (crowd.valid()) current.destroyCrowd(crowd);
    if (terrainHandle.valid()) current.destroyTerrain(terrainHandle);
    characters.clear();
    subdivs.clear();
    crowd = {};
    terrainHandle = {};
    if (release == Release::Park && parkBackends) {
        // Kept initialised, with no scene objects, for a switch back: its
        // pipelines are what a switch spends its time on (seconds on a
        // software rasterizer).
        const std::string name = selected->capabilities.name;
        parked[name] = {std::move(selected->backend), selected->capabilities};
    } else if (release != Release::Keep) {
        current.shutdown();
    }
    // Deferred destructions wait for frames in flight; there are none now.
    if (scheduler) scheduler->waitIdle();
}

void RenderSession::Impl::restoreBackend(const Options& options, const std::string& previous) {
    selected->backend.reset();
    ParkedBackend back;
    bool warm = false;
    if (auto it = parked.find(previous); it != parked.end()) {
        back = std::move(it->second);
        parked.erase(it);
        warm = true;
    } else if (auto created = createBackendOnDevice(*selected, options, previous, back.capabilities); created) {
        back.backend = std::move(created.value());
    }
    if (!back.backend) return;
    selected->backend = std::move(back.backend);
    selected->capabilities = back.capabilities;
    if (Status again = initializeBackend(warm); !again)
        log::error("backend " + previous + ": " + reporter->wording(again.error()));
}

Status RenderSession::switchBackend(const Options& options, const std::string& name, terrain::Terrain* terrain) {
    TESSERA_CPU_SCOPE("session.switchBackend");
    Impl& s = *mImpl;
    const auto start = std::chrono::steady_clock::now();
    const std::string previous = capabilities().name;
    if (name == previous && s.parkBackends) {
        // The same backend again (a world loaded anew): keep it, re-create
        // the scene on it.
        s.releaseBackend(Impl::Release::Keep);
        if (terrain) s.terrain = terrain;
        return s.initializeBackend(true);
    }
    Impl::ParkedBackend next;
    bool warm = false;
    if (auto it = s.parked.find(name); it != s.parked.end()) {
        next = std::move(it->second);
        s.parked.erase(it);
        warm = true;
    } else {
        auto created = createBackendOnDevice(*s.selected, options, name, next.capabilities);
        if (!created) return created.error();
        next.backend = std::move(created.value());
    }
    s.releaseBackend(Impl::Release::Park);
    if (terrain) s.terrain = terrain;
    s.selected->backend = std::move(next.backend);
    s.selected->capabilities = next.capabilities;
    Status ok = s.initializeBackend(warm);
    if (!ok) {
        // Leave the session drawing as before rather than with no backend.
        s.restoreBackend(options, previous);
        return fail("switching to backend ", name, ": ", ok.error().message);
    }
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    log::info("switched backend " + previous + " -> " + name + " on " + deviceName() + " (" + std::to_string(int(ms)) +
              " ms" + (warm ? ", kept from before" : "") + "; the scene uploads follow)");
    return {};
}

} // namespace tessera::runtime
