#pragma once
/// @file BasicTerrainBackend.h
/// The first pass the three GPU backends share: the terrain's control mesh,
/// untessellated, displaced by vertex texture fetch and shaded from the
/// height map. Each backend derives from it, states its own capabilities and
/// replaces drawTerrain with its own technique for the tessellated modes.
///
/// The frame's main pass (into the host's target) opens lazily on the first
/// draw, so a backend can run its own off-target passes (R2VB render targets,
/// stream-out, compute) before it.

#include "GpuTerrain.h"
#include "tessera/backend/Backend.h"
#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/Pipeline.h"
#include "tessera/gpu/PipelineLayout.h"

#include <memory>
#include <optional>
#include <vector>


namespace tessera::backends {

class BasicTerrainBackend : public backend::Backend {
public:
    Status initialize(const backend::BackendInitInfo& info) override;
    void shutdown() override;
    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc& desc) override;
    void destroyTerrain(backend::TerrainHandle terrain) override;
    void beginFrame(const backend::FrameInfo& frame) override;
    void drawTerrain(backend::TerrainHandle terrain, const backend::TerrainDrawInfo& draw) override;
    void endFrame() override;
    backend::FrameReport lastFrameReport() override { return mLastReport; }

protected:
    /// Checks `device` against what the derived backend needs; shared by the
    /// capability queries so every backend words missing features the same way.
    static void checkRequirements(const backend::DeviceFeatures* device, backend::BackendCapabilities& caps);

    /// Opens the main pass into the host's target if it is not open yet.
    void ensureMainPass();
    /// Draws `tiles` of `terrain` as the untessellated control mesh.
    void drawControlMesh(GpuTerrain& terrain, std::span<const uint32_t> tiles, const char* passName);

    gpu::Device* mDevice = nullptr;
    gpu::FrameContext* mFrame = nullptr;
    backend::FrameInfo mFrameInfo;
    gpu::UniformSlice mFrameUniforms;
    backend::FrameReport mReport;
    backend::FrameReport mLastReport;

private:
    gpu::PipelineLayout mLayout;
    gpu::Pipeline mFillPipeline;
    gpu::Pipeline mWirePipeline;
    std::vector<std::unique_ptr<GpuTerrain>> mTerrains;
    bool mMainPassOpen = false;
};

} // namespace tessera::backends
