// The null backend runs the whole frame logic with no GPU: terrain patches,
// camera, culling, tessellation levels, splats and the backend contract, in
// the host's order.
#include "tessera/backend/PluginLoader.h"
#include "tessera/backend/RecordingBackend.h"
#include "tessera/scene/Camera.h"
#include "tessera/terrain/Terrain.h"

#include <gtest/gtest.h>

using namespace tessera;

namespace {

terrain::HeightField makeRamp(uint32_t n) {
    std::vector<uint16_t> samples(size_t(n) * n);
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) samples[size_t(j) * n + i] = uint16_t(i * 65535u / (n - 1));
    return terrain::HeightField(n, n, std::move(samples), terrain::TerrainScale{4.0f, 400.0f});
}

struct NullFixture {
    backend::PluginLoader loader;
    backend::BackendRegistry registry;
    backend::BackendPtr backend;

    NullFixture() {
        loader.addSearchDirectory(TESSERA_PLUGIN_DIR);
        EXPECT_TRUE(loader.loadBackend("null", registry).ok());
        auto created = registry.create("null");
        EXPECT_TRUE(created.ok());
        if (created.ok()) backend = std::move(created.value());
    }
};

terrain::TessellationSettings settingsFor(terrain::TerrainMode mode, float continuousLevel = 15.0f) {
    terrain::TessellationSettings s;
    s.mode = mode;
    s.continuousLevel = continuousLevel;
    return s;
}

} // namespace

TEST(NullBackendFrame, CullsPatchesAndDrivesTheContractInOrder) {
    NullFixture null;
    ASSERT_TRUE(null.backend);
    backend::RecordingBackend backend(*null.backend);
    const backend::BackendCapabilities caps = backend.capabilities(nullptr);
    EXPECT_FALSE(caps.requiresGpu);
    EXPECT_EQ(caps.maxTessFactor, 64.0f);
    EXPECT_TRUE(caps.drawsTerrainMode(terrain::TerrainMode::LowRes));
    EXPECT_TRUE(caps.drawsTerrainMode(terrain::TerrainMode::Continuous));
    EXPECT_TRUE(caps.drawsTerrainMode(terrain::TerrainMode::Adaptive));

    terrain::Terrain terrain(makeRamp(257), 8);
    ASSERT_TRUE(backend.initialize({}).ok());
    auto terrainHandle = backend.createTerrain({&terrain});
    ASSERT_TRUE(terrainHandle.ok());

    // Looking straight down from high above the centre sees every patch;
    // looking away from the terrain sees none.
    scene::Camera camera;
    camera.setAspect(1.0f);
    std::vector<uint32_t> visible;
    camera.setPose({{512.0f, 5000.0f, 512.0f}, 0.0f, glm::radians(-89.9f)});
    terrain.cull(camera.frustum(), camera.position(), visible);
    EXPECT_EQ(visible.size(), 64u);

    const terrain::CraterSplat craters[2] = {{{300.0f, 300.0f}, 40.0f, {}}, {{700.0f, 500.0f}, 60.0f, {}}};
    for (const auto& crater : craters) terrain.splat(crater);
    const std::vector<terrain::CraterSplat> pending = terrain.takePendingSplats();

    backend.beginFrame({});
    backend.splatTerrain(terrainHandle.value(), pending);
    backend.drawTerrain(terrainHandle.value(), {visible, settingsFor(terrain::TerrainMode::LowRes)});
    backend.endFrame();
    auto report = backend.lastFrameReport();
    EXPECT_EQ(report.terrainPatchesDrawn, 64u);
    EXPECT_EQ(report.splatsApplied, 2u);
    EXPECT_EQ(report.trianglesSubmitted, 64u * 2u);
    // With no GPU copy, the readback is the CPU copy, craters included.
    auto heights = backend.readTerrainHeights(terrainHandle.value());
    ASSERT_TRUE(heights.ok());
    EXPECT_EQ(heights.value(), terrain.field().samples());

    visible.clear();
    camera.setPose({{512.0f, 5000.0f, 512.0f}, 0.0f, glm::radians(89.9f)});
    terrain.cull(camera.frustum(), camera.position(), visible);
    EXPECT_TRUE(visible.empty());

    backend.destroyTerrain(terrainHandle.value());
    EXPECT_FALSE(backend.readTerrainHeights(terrainHandle.value()).ok());
    backend.shutdown();
    EXPECT_EQ(backend.commands(),
              (std::vector<std::string>{"capabilities", "initialize", "createTerrain", "beginFrame", "splatTerrain",
                                        "drawTerrain", "endFrame", "lastFrameReport", "readTerrainHeights",
                                        "destroyTerrain", "readTerrainHeights", "shutdown"}));
}

TEST(NullBackendFrame, CountsTessellatedTriangles) {
    NullFixture null;
    ASSERT_TRUE(null.backend);
    backend::Backend& backend = *null.backend;
    ASSERT_TRUE(backend.initialize({}).ok());
    terrain::Terrain terrain(makeRamp(129), 4);
    auto handle = backend.createTerrain({&terrain});
    ASSERT_TRUE(handle.ok());
    const std::vector<uint32_t> patches{0, 5, 10, 15, 99}; // 99 is out of range and skipped

    scene::Camera camera;
    camera.setPose({{256.0f, 600.0f, 256.0f}, 0.0f, glm::radians(-90.0f)});
    backend::FrameInfo frame;
    frame.cameraPosition = camera.position();
    frame.projection = camera.projection();
    frame.height = 720;

    auto draw = [&](const terrain::TessellationSettings& settings) {
        backend.beginFrame(frame);
        backend.drawTerrain(handle.value(), {patches, settings});
        backend.endFrame();
        const backend::FrameReport report = backend.lastFrameReport();
        EXPECT_EQ(report.terrainPatchesDrawn, 4u);
        return report.trianglesSubmitted;
    };
    using terrain::TerrainMode;
    // A uniform odd level n makes an n x n grid of quads: 2 n^2 triangles.
    EXPECT_EQ(draw(settingsFor(TerrainMode::Continuous, 15.0f)), 4u * 2u * 15u * 15u);
    // fractional_odd rounds 2 up to 3, and 64 down to 63.
    EXPECT_EQ(draw(settingsFor(TerrainMode::Continuous, 2.0f)), 4u * 2u * 3u * 3u);
    EXPECT_EQ(draw(settingsFor(TerrainMode::Continuous, 64.0f)), 4u * 2u * 63u * 63u);
    // All levels 1: the untessellated quad.
    EXPECT_EQ(draw(settingsFor(TerrainMode::Continuous, 1.0f)), 4u * 2u);
    EXPECT_EQ(draw(settingsFor(TerrainMode::LowRes)), 4u * 2u);

    // Adaptive with min == max: uniform again, through the metric path.
    terrain::TessellationSettings fixed = settingsFor(TerrainMode::Adaptive);
    fixed.minLevel = fixed.maxLevel = 5.0f;
    EXPECT_EQ(draw(fixed), 4u * 2u * 5u * 5u);
    // Adaptive screen-space levels vary per edge: between the extremes.
    const uint64_t adaptive = draw(settingsFor(TerrainMode::Adaptive));
    EXPECT_GT(adaptive, 4u * 2u);
    EXPECT_LT(adaptive, 4u * 2u * 63u * 63u);

    backend.destroyTerrain(handle.value());
    backend.shutdown();
}
