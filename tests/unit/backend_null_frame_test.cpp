// The null backend runs the whole frame logic with no GPU: terrain tiling,
// camera, frustum culling and the backend contract, in the host's order.
#include "tessera/backend/PluginLoader.h"
#include "tessera/backend/RecordingBackend.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/SceneGraph.h"
#include "tessera/terrain/TerrainTiles.h"

#include <gtest/gtest.h>

using namespace tessera;

namespace {

terrain::HeightField makeRamp(uint32_t n) {
    std::vector<uint16_t> samples(size_t(n) * n);
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) samples[size_t(j) * n + i] = uint16_t(i * 65535u / (n - 1));
    return terrain::HeightField(n, n, std::move(samples), terrain::TerrainScale{4.0f, 400.0f});
}

} // namespace

TEST(NullBackendFrame, CullsTilesAndDrivesTheContractInOrder) {
    backend::PluginLoader loader;
    loader.addSearchDirectory(TESSERA_PLUGIN_DIR);
    backend::BackendRegistry registry;
    ASSERT_TRUE(loader.loadBackend("null", registry).ok());
    auto created = registry.create("null");
    ASSERT_TRUE(created.ok());
    backend::RecordingBackend backend(*created.value());
    EXPECT_FALSE(backend.capabilities(nullptr).requiresGpu);

    terrain::HeightField field = makeRamp(257);
    scene::SceneGraph scene;
    terrain::TerrainTiles tiles(scene, field, 8);
    ASSERT_TRUE(backend.initialize({}).ok());
    auto terrainHandle = backend.createTerrain({&field, 8, 16});
    ASSERT_TRUE(terrainHandle.ok());

    // Looking straight down from high above the centre sees every tile;
    // looking away from the terrain sees none.
    scene::Camera camera;
    camera.setAspect(1.0f);
    std::vector<uint32_t> visible;
    camera.setPose({{512.0f, 5000.0f, 512.0f}, 0.0f, glm::radians(-89.9f)});
    tiles.cull(camera.frustum(), camera.position(), visible);
    EXPECT_EQ(visible.size(), 64u);

    backend.beginFrame({});
    backend.drawTerrain(terrainHandle.value(), {visible, backend::TerrainMode::LowRes});
    backend.endFrame();
    auto report = backend.lastFrameReport();
    EXPECT_EQ(report.terrainTilesDrawn, 64u);
    EXPECT_EQ(report.trianglesSubmitted, 64u * 16u * 16u * 2u);

    visible.clear();
    camera.setPose({{512.0f, 5000.0f, 512.0f}, 0.0f, glm::radians(89.9f)});
    tiles.cull(camera.frustum(), camera.position(), visible);
    EXPECT_TRUE(visible.empty());

    backend.destroyTerrain(terrainHandle.value());
    backend.shutdown();
    EXPECT_EQ(backend.commands(), (std::vector<std::string>{"capabilities", "initialize", "createTerrain", "beginFrame",
                                                            "drawTerrain", "endFrame", "lastFrameReport",
                                                            "destroyTerrain", "shutdown"}));
}

TEST(NullBackendFrame, TileBoundsFollowTheHeightField) {
    terrain::HeightField field = makeRamp(129);
    scene::SceneGraph scene;
    terrain::TerrainTiles tiles(scene, field, 4);
    // The ramp rises along x: the first column of tiles is lowest, the last highest.
    EXPECT_NEAR(tiles.tileBounds(0).min.y, 0.0f, 1e-3f);
    EXPECT_NEAR(tiles.tileBounds(3).max.y, 400.0f, 1e-3f);
    EXPECT_LT(tiles.tileBounds(0).max.y, tiles.tileBounds(3).min.y + 1e-3f);
}
