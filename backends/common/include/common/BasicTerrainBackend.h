#pragma once
/// @file BasicTerrainBackend.h
/// What the three GPU backends share: terrain upload, crater splats into the
/// GPU height map, its readback, and the untessellated control mesh (the
/// paper's low-resolution mode), displaced by vertex texture fetch and shaded
/// from the height map. Each backend derives from it, states its capabilities
/// and draws the tessellated modes with its own technique (drawTessellated).
///
/// The frame's main pass (into the host's target) opens lazily on the first
/// draw, so a backend can run its own off-target passes (R2VB render targets,
/// stream-out, compute) before it. In the full look the frame's terrain is
/// shaded after the main pass by the terrain resolve (TerrainResolvePass),
/// which also draws the sky; with no terrain the sky pass draws it.

#include "common/CharacterShadowPass.h"
#include "common/GpuTerrain.h"
#include "common/SkyPass.h"
#include "common/TerrainSplatPass.h"
#include "common/TerrainResolvePass.h"
#include "common/TerrainSunPass.h"
#include "tessera/backend/Backend.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <memory>
#include <vector>

namespace tessera::backends {

class BasicTerrainBackend : public backend::Backend {
public:
    Status initialize(const backend::BackendInitInfo& info) override;
    void shutdown() override;
    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc& desc) override;
    void destroyTerrain(backend::TerrainHandle terrain) override;
    void beginFrame(const backend::FrameInfo& frame) override;
    void splatTerrain(backend::TerrainHandle terrain, std::span<const terrain::CraterSplat> splats) override;
    void drawTerrain(backend::TerrainHandle terrain, const backend::TerrainDrawInfo& draw) override;
    Result<std::vector<uint16_t>> readTerrainHeights(backend::TerrainHandle terrain) override;
    void endFrame() override;
    backend::FrameReport lastFrameReport() override { return mLastReport; }

protected:
    /// Checks `device` against what the derived backend needs; shared by the
    /// capability queries so every backend words missing features the same way.
    static void checkRequirements(const device::DeviceFeatures* device, backend::BackendCapabilities& caps);

    /// How the full look's terrain resolve runs: a fullscreen fragment pass
    /// unless the backend has compute (TerrainResolvePass).
    virtual TerrainResolvePass::Mode terrainResolveMode() const { return TerrainResolvePass::Mode::Fragment; }
    /// Creates the derived backend's own pipelines, after the shared ones.
    virtual Status initializeTechnique(const backend::BackendInitInfo&) { return {}; }
    virtual void shutdownTechnique() {}
    /// Draws a continuous or adaptive terrain; called only for modes the
    /// backend's capabilities list, with maxLevel already clamped to its maximum.
    virtual void drawTessellated(GpuTerrain&, const backend::TerrainDrawInfo&) {}

    /// Opens the main pass into the host's target if it is not open yet
    /// (clearing it the first time in a frame, keeping its contents after).
    void ensureMainPass();
    /// Closes the main pass if open, so an off-target pass can run.
    void suspendMainPass();
    /// Draws the visible patches of `terrain` as the untessellated control mesh.
    void drawControlMesh(GpuTerrain& terrain, std::span<const uint32_t> patches, const char* passName);
    /// Pushes the frame, terrain, height-map, sun-visibility, detail and
    /// character-shadow bindings (set 0: 0..2, TS_BINDING_SUN_VISIBILITY,
    /// TS_BINDING_DETAIL, TS_BINDING_CHARACTER_SHADOW) plus `extra` writes
    /// for `layout`, which must declare all six.
    void pushTerrainDescriptors(VkPipelineBindPoint bindPoint, const gpu::PipelineLayout& layout, GpuTerrain& terrain,
                                std::span<const VkWriteDescriptorSet> extra = {});
    /// Pixels one metre covers seen face-on from one metre away (the metrics' scale).
    float pixelsPerMetre() const;
    /// This frame's shader::TerrainTessUniforms for a draw of `terrain`, with
    /// every level clamped to [1, maxLevel] (the backend's maximum).
    gpu::UniformSlice pushTessUniforms(const GpuTerrain& terrain, const terrain::TessellationSettings& settings,
                                       float maxLevel);

    gpu::Device* mDevice = nullptr;
    gpu::FrameContext* mFrame = nullptr;
    backend::FrameInfo mFrameInfo;
    gpu::UniformSlice mFrameUniforms;
    backend::FrameReport mReport;
    backend::FrameReport mLastReport;
    bool mWireframeSupported = false;

private:
    GpuTerrain* find(backend::TerrainHandle handle);

    gpu::PipelineLayout mLayout;
    gpu::Pipeline mFillPipeline;
    gpu::Pipeline mWirePipeline;
    TerrainSplatPass mSplatPass;
    TerrainSunPass mSunPass;
    CharacterShadowPass mShadowPass;
    SkyPass mSkyPass;
    TerrainResolvePass mResolvePass;
    std::vector<std::unique_ptr<GpuTerrain>> mTerrains;
    /// The full look's terrain this frame, shaded by mResolvePass after the
    /// main pass; a second terrain in the same frame is shaded forward.
    GpuTerrain* mResolveTerrain = nullptr;
    /// This frame's terrain is shaded deferred (FrameInfo::terrainShading).
    bool mDeferTerrain = false;
    /// TerrainShading::Auto defers: with the compute resolve on a GPU.
    bool mDeferOnAuto = false;
    bool mMainPassOpen = false;
    bool mMainPassStarted = false;
};

} // namespace tessera::backends
