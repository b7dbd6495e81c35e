// The null backend: the whole frame logic with no GPU (bgfx's and sokol's
// noop renderer). It validates every call the way a real backend would use
// it and counts what a real backend would draw, so tests of the data model
// (scene, culling, LOD, terrain tiling) run anywhere, CI included.
#include "tessera/backend/PluginApi.h"

#include <vector>

namespace tessera::backends {
namespace {

class NullBackend final : public backend::Backend {
public:
    backend::BackendCapabilities capabilities(const backend::DeviceFeatures*) override {
        backend::BackendCapabilities caps;
        caps.name = "null";
        caps.description = "no GPU: runs the frame logic and counts what would be drawn";
        caps.requiresGpu = false;
        return caps;
    }

    Status initialize(const backend::BackendInitInfo&) override {
        mInitialized = true;
        return {};
    }

    void shutdown() override {
        mTerrains.clear();
        mInitialized = false;
    }

    Result<backend::TerrainHandle> createTerrain(const backend::TerrainDesc& desc) override {
        if (!mInitialized) return fail("null backend: createTerrain before initialize");
        if (!desc.heightField) return fail("createTerrain: no height field");
        if (desc.tilesPerSide == 0 || desc.quadsPerTile == 0) return fail("createTerrain: empty tiling");
        mTerrains.push_back(Terrain{desc.tilesPerSide * desc.tilesPerSide, desc.quadsPerTile, true});
        return backend::TerrainHandle{static_cast<uint32_t>(mTerrains.size() - 1)};
    }

    void destroyTerrain(backend::TerrainHandle terrain) override {
        if (terrain.valid() && terrain.id < mTerrains.size()) mTerrains[terrain.id].alive = false;
    }

    void beginFrame(const backend::FrameInfo& frame) override {
        mReport = {};
        mReport.frameIndex = frame.frameIndex;
    }

    void drawTerrain(backend::TerrainHandle handle, const backend::TerrainDrawInfo& draw) override {
        if (!handle.valid() || handle.id >= mTerrains.size() || !mTerrains[handle.id].alive) return;
        const Terrain& t = mTerrains[handle.id];
        uint32_t drawn = 0;
        for (uint32_t tile : draw.visibleTiles)
            if (tile < t.tileCount) ++drawn;
        mReport.terrainTilesDrawn += drawn;
        mReport.trianglesSubmitted += uint64_t(drawn) * t.quadsPerTile * t.quadsPerTile * 2;
        ++mReport.passes;
    }

    void endFrame() override { mLast = mReport; }

    backend::FrameReport lastFrameReport() override { return mLast; }

private:
    struct Terrain {
        uint32_t tileCount;
        uint32_t quadsPerTile;
        bool alive;
    };
    std::vector<Terrain> mTerrains;
    backend::FrameReport mReport;
    backend::FrameReport mLast;
    bool mInitialized = false;
};

backend::Backend* createNull() { return new NullBackend(); }
void destroyNull(backend::Backend* b) { delete b; }

} // namespace
} // namespace tessera::backends

TESSERA_REGISTER_PLUGIN(registry) {
    registry.registerBackend({"null", &tessera::backends::createNull, &tessera::backends::destroyNull});
}
