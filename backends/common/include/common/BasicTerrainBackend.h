#pragma once
/// @file BasicTerrainBackend.h
/// The base of every GPU backend and the first layer of the shared chain
///   BasicTerrainBackend -> BasicSubdivBackend -> BasicCharacterBackend
///   (-> EmulatedTerrainBackend for the emulated tessellator),
/// which implements each whole-job command of the contract once, as
/// Filament's renderer keeps the order of work above its drivers: a backend
/// supplies only its technique, through the protected hooks of each layer
/// (plugins/BackendTemplate/README.md lists them).
///
/// This layer: the frame, terrain upload, crater splats into the GPU height
/// map, its readback, and the untessellated control mesh (the paper's
/// low-resolution mode), displaced by vertex texture fetch and shaded from
/// the height map; a backend draws the tessellated modes with its own
/// technique (drawTessellated).
///
/// The frame's main pass (into the host's target) opens lazily on the first
/// draw, so a backend can run its own off-target passes (R2VB render targets,
/// stream-out, compute) before it. In the full look the frame's terrain is
/// shaded after the main pass by the terrain resolve (TerrainResolvePass),
/// which also draws the sky; with no terrain the sky pass draws it.
///
/// With cascaded shadows (CascadedShadowMaps) the terrain receives the
/// characters' shadows, whose depth passes the character and crowd commands
/// record after it: drawTerrain then updates the terrain's own maps at once
/// but keeps its main-pass draw (the visible patches copied) and records it
/// in endFrame, after every caster and before the sky.
///
/// Submitting and waiting: between beginFrame and endFrame a backend only
/// records into the host's FrameContext; it never submits, presents or
/// waits. Outside a frame it blocks only through the GPU layer, each in one
/// place: creation-time uploads through gpu::Buffer::upload and
/// gpu::Image::upload, the contract's blocking reads (readTerrainHeights,
/// readCrowdTiers, readSubdivPoints) through gpu::readBack, and shutdown
/// through Device::waitIdle.

#include "common/CascadedShadowMaps.h"
#include "common/CharacterShadowPass.h"
#include "common/FillWirePipelines.h"
#include "common/GpuObjectTable.h"
#include "common/GpuTerrain.h"
#include "common/SkyPass.h"
#include "common/TerrainBindings.h"
#include "common/TerrainSplatPass.h"
#include "common/TerrainResolvePass.h"
#include "common/TerrainSunPass.h"
#include "tessera/backend/Backend.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <span>
#include <functional>
#include <vector>

namespace tessera::backends {

class BasicTerrainBackend : public backend::Backend {
public:
    // The contract's frame and terrain commands, written once for every GPU
    // backend (final: a backend supplies the hooks below instead).
    /// describeCapabilities(), with what `device` lacks of it in `missing`.
    backend::BackendCapabilities capabilities(const device::DeviceFeatures* device) final;
    Status initialize(const backend::BackendInitInfo& info) final;
    void shutdown() final;
    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc& desc) final;
    void destroyTerrain(backend::TerrainHandle terrain) final;
    void beginFrame(const backend::FrameInfo& frame) final;
    void splatTerrain(backend::TerrainHandle terrain, std::span<const terrain::CraterSplat> splats) final;
    void drawTerrain(backend::TerrainHandle terrain, const backend::TerrainDrawInfo& draw) final;
    Result<std::vector<uint16_t>> readTerrainHeights(backend::TerrainHandle terrain) final;
    void endFrame() final;
    backend::FrameReport lastFrameReport() final { return mLastReport; }

protected:
    // What a backend supplies (its technique).
    /// What the backend is and does: its name and description, tessellation
    /// path and maximum level, terrain modes, crowds and surfaces, and the
    /// device features it uses (BackendCapabilities' uses* fields), which
    /// capabilities() checks against a device in one wording for all.
    virtual backend::BackendCapabilities describeCapabilities() const = 0;
    /// How the full look's terrain resolve runs: a fullscreen fragment pass
    /// unless the backend has compute (TerrainResolvePass).
    virtual TerrainResolvePass::Mode terrainResolveMode() const { return TerrainResolvePass::Mode::Fragment; }
    /// Creates the derived backend's own pipelines, after the shared ones.
    virtual Status initializeTechnique(const backend::BackendInitInfo&) { return {}; }
    /// Releases them (the device is idle and every object already released).
    virtual void shutdownTechnique() {}
    /// Resets the technique's per-frame state, at the end of beginFrame.
    virtual void beginTechniqueFrame() {}
    /// Refuses, before anything is made, a terrain the technique cannot draw
    /// on this device (a device limit), with a message naming it.
    virtual Status checkTerrain(const backend::TerrainDesc&) { return {}; }
    /// Draws a continuous or adaptive terrain; called only for modes the
    /// backend's capabilities list, with maxLevel already clamped to its maximum.
    virtual void drawTessellated(GpuTerrain&, const backend::TerrainDrawInfo&) {}

    /// Releases every object the create commands made, at shutdown once the
    /// device is idle: each layer of the class chain releases its own table,
    /// then calls its base's.
    virtual void releaseObjects() { mTerrains.clear(); }

    // What the shared sequencing offers a technique.
    /// Opens the main pass into the host's target if it is not open yet
    /// (clearing it the first time in a frame, keeping its contents after).
    void ensureMainPass();
    /// Closes the main pass if open, so an off-target pass can run.
    void suspendMainPass();
    /// A terrain's draw in the main pass: GPU pass "terrain.continuous" or
    /// "terrain.adaptive" by `mode`, in which `record` records the draw of
    /// `patches` visible patches and says whether it drew (the report then
    /// counts them). At once on a GPU or when the main pass is open; on a
    /// CPU rasterizer otherwise first thing when the main pass next opens,
    /// so the crowd's and characters' own passes come before it. Why:
    /// lavapipe waits at every barrier until everything it has binned is
    /// rasterized, so an off-target pass between the terrain's draw and the
    /// crowd's held the crowd's vertex work until the terrain was
    /// rasterized; in this order the two overlap (docs/BACKENDS.md, "Frame
    /// order on a CPU rasterizer").
    void drawTerrainInMainPass(backend::TerrainMode mode, uint32_t patches, std::function<bool()> record);
    /// Draws the visible patches of `terrain` as the untessellated control mesh.
    void drawControlMesh(GpuTerrain& terrain, std::span<const uint32_t> patches, const char* passName);
    /// Pushes the terrain's shared bindings (TerrainBindings.h) plus `extra`
    /// writes for `layout`, which terrainLayout made.
    void pushTerrainDescriptors(VkPipelineBindPoint bindPoint, const gpu::PipelineLayout& layout, GpuTerrain& terrain,
                                std::span<const VkWriteDescriptorSet> extra = {});
    /// pushTerrainDescriptors for `terrain` as a callable for the pass objects.
    PushTerrainBindings terrainPush(GpuTerrain& terrain);
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
    /// This frame draws cascaded shadow maps rather than blob shadows
    /// (FrameInfo::shadows, where capabilities().cascadedShadows).
    bool mCascadedShadows = false;
    /// The cascaded shadow maps: written by the casters' depth-only passes
    /// (BasicCharacterBackend), read through every receiver layout.
    CascadedShadowMaps mShadowMaps;

private:
    /// A terrain draw kept for endFrame (cascaded shadows), its patches owned.
    struct PendingTerrainDraw {
        GpuTerrain* terrain = nullptr;
        std::vector<uint32_t> patches;
        terrain::TessellationSettings tessellation;
    };
    /// drawTerrain's main-pass part: picks the terrain the resolve shades,
    /// then draws its patches (control mesh or the technique's).
    void recordTerrainDraw(GpuTerrain& terrain, const backend::TerrainDrawInfo& draw);

    /// Adds to `caps.missing` what `device` lacks of what `caps` uses.
    static void checkRequirements(const device::DeviceFeatures* device, backend::BackendCapabilities& caps);

    gpu::PipelineLayout mLayout;
    FillWirePipelines mPipelines;
    TerrainSplatPass mSplatPass;
    TerrainSunPass mSunPass;
    CharacterShadowPass mShadowPass;
    SkyPass mSkyPass;
    TerrainResolvePass mResolvePass;
    GpuObjectTable<GpuTerrain, backend::TerrainHandle> mTerrains;
    /// The full look's terrain this frame, shaded by mResolvePass after the
    /// main pass; a second terrain in the same frame is shaded forward.
    GpuTerrain* mResolveTerrain = nullptr;
    /// This frame's terrain draws waiting for the casters (cascaded shadows).
    std::vector<PendingTerrainDraw> mPendingTerrains;
    /// Terrain draws waiting for the main pass to open (drawTerrainInMainPass).
    std::vector<std::function<void()>> mMainPassDraws;
    /// This frame's terrain is shaded deferred (FrameInfo::terrainShading).
    bool mDeferTerrain = false;
    /// TerrainShading::Auto defers: with the compute resolve on a GPU.
    bool mDeferOnAuto = false;
    /// Shadows::Auto picks cascaded shadows: where they cost little on the device.
    bool mCascadedOnAuto = false;
    bool mMainPassOpen = false;
    bool mMainPassStarted = false;
};

} // namespace tessera::backends
