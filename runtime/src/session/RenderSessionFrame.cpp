// RenderSession: recording and submitting a frame (the rest of the class is
// in RenderSession.cpp and RenderSessionSwitch.cpp).
#include "session/RenderSessionImpl.h"

#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/runtime/World.h"
#include "tessera/core/Log.h"
#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/scene/ShadowCascadeFit.h"

namespace tessera::runtime {
namespace {

/// The frame's counters in the trace: what the backend drew, as it reports it.
void recordCounters(uint32_t frameIndex, const backend::FrameReport& report, bool characters, bool crowd) {
    auto& profiler = profiler::Profiler::global();
    auto record = [&profiler, frameIndex](const char* name, double value) {
        profiler.recordCounter({name, uint64_t(frameIndex), profiler.nowNs(), value});
    };
    record("patches drawn", double(report.terrainPatchesDrawn));
    record("craters splatted", double(report.splatsApplied));
    if (characters) record("character triangles", double(report.characterTriangles));
    if (!crowd) return;
    // The GPU's own counts (a backend reads them back a few frames late).
    static const char* const kTierCounters[TS_LOD_TIERS] = {"crowd near instances", "crowd middle instances",
                                                            "crowd far instances", "crowd impostor instances"};
    for (uint32_t t = 0; t < TS_LOD_TIERS; ++t) record(kTierCounters[t], double(report.crowdInstances[t]));
}

} // namespace

backend::FrameInfo RenderSession::Impl::frameInfo(uint32_t index, const scene::Camera& camera,
                                                  const glm::vec3& clearColor, bool wireframe) const {
    backend::FrameInfo info;
    info.frameIndex = index;
    info.timeSeconds = index * World::kSecondsPerFrame;
    info.view = camera.view();
    info.projection = camera.projection();
    info.viewProjection = camera.viewProjection();
    info.cameraPosition = camera.position();
    info.clearColor = glm::vec4(clearColor, 1.0f);
    info.width = width;
    info.height = height;
    info.wireframe = wireframe;
    if (terrainVisible) {
        info.shadowCasters = shadowCasters;
        info.shadowRegion = shadowRegion;
    }
    info.look = look;
    info.terrainShading = terrainShading;
    info.shadows = shadows;
    info.shadowCascades = shadowCascades;
    info.sunDirection = sunDirection;
    return info;
}

void RenderSession::Impl::endCapture(uint32_t index) {
    auto file = renderDoc->end(*selected->instance);
    if (!file) {
        reporter->warning(failSetting(setting::kRenderDocFrame, ": ", file.error().message));
        return;
    }
    captureFile = file.value();
    log::info("RenderDoc capture of frame " + std::to_string(index) + ": " + captureFile.string());
}

void RenderSession::renderFrame(uint32_t frameIndex, const scene::Camera& camera,
                                const terrain::TessellationSettings& settings, const glm::vec3& clearColor,
                                bool wireframe, bool readback, const backend::CharacterDrawInfo* characters,
                                const backend::CrowdDrawInfo* crowd, std::span<const SubdivDraw> surfaces) {
    Impl& s = *mImpl;
    backend::Backend& backend = *s.selected->backend;
    s.frameIndex = frameIndex;
    s.visible.clear();
    {
        TESSERA_CPU_SCOPE("terrain.cull");
        if (s.terrainVisible) s.terrain->cull(camera.frustum(), camera.position(), s.visible);
    }
    const std::vector<terrain::CraterSplat> splats = s.terrain->takePendingSplats();
    // The cascades follow the view; fitted only where a backend may draw
    // them, with the device's settings (the backend's layers have them too).
    s.shadowCascades.clear();
    const bool mayCascade = s.shadows == backend::Shadows::Auto || s.shadows == backend::Shadows::Cascaded;
    if (s.look == backend::Look::Full && mayCascade && capabilities().cascadedShadows)
        s.shadowCascades =
            scene::ShadowCascadeFit(scene::ShadowCascadeFit::Settings::forDevice(deviceClass())).fit(camera, s.sunDirection);
    backend::FrameInfo info = s.frameInfo(frameIndex, camera, clearColor, wireframe);
    const bool capture = s.renderDoc && s.captureFrame == frameIndex;
    if (capture) s.renderDoc->begin(*s.selected->instance);
    {
        TESSERA_CPU_SCOPE("render.record");
        if (s.scheduler) info.gpu = &s.scheduler->beginFrame(frameIndex);
        backend.beginFrame(info);
        backend.splatTerrain(s.terrainHandle, splats);
        if (s.terrainVisible) backend.drawTerrain(s.terrainHandle, {s.visible, settings});
        if (characters) backend.drawCharacters(*characters);
        if (crowd && s.crowd.valid()) backend.drawCrowd(s.crowd, *crowd);
        for (const SubdivDraw& surface : surfaces) {
            if (!surface.tileRects.empty()) backend.updateSubdivTiles(surface.handle, surface.tiles, surface.tileRects);
            backend.drawSubdiv(surface.handle, surface.info);
        }
        backend.endFrame();
        if (s.overlay && info.gpu) s.overlay(*info.gpu);
    }
    if (s.scheduler) {
        TESSERA_CPU_SCOPE("render.submit");
        s.scheduler->endFrame(readback, s.swapchain.get());
    }
    if (capture) s.endCapture(frameIndex);
    recordCounters(frameIndex, backend.lastFrameReport(), characters != nullptr, crowd != nullptr);
}

} // namespace tessera::runtime
