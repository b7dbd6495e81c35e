// Terrain::cull: the min/max pyramid walk finds exactly the patches whose true
// displaced bounds meet the frustum, as testing every patch would.

#include "tessera/core/Random.h"
#include "tessera/scene/Camera.h"
#include "tessera/terrain/Terrain.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace tessera;
using terrain::HeightField;
using terrain::Terrain;

namespace {

constexpr uint32_t kSize = 257; // 256 spacings of 4 m: 1024 m

HeightField makeField(uint16_t (*value)(uint32_t, uint32_t)) {
    std::vector<uint16_t> v(size_t(kSize) * kSize);
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) v[size_t(j) * kSize + i] = value(i, j);
    return HeightField(kSize, kSize, std::move(v), terrain::TerrainScale{4.0f, 600.0f});
}

uint16_t hills(uint32_t i, uint32_t j) {
    return uint16_t(20000.0 + 15000.0 * std::sin(i * 0.05) * std::cos(j * 0.037) + 5000.0 * std::sin((i + j) * 0.21));
}

uint16_t flat(uint32_t, uint32_t) {
    return 0;
}

// Flat ground at zero with a single 550 m spike at sample (128, 150): x 512 m, z 600 m.
uint16_t spike(uint32_t i, uint32_t j) {
    return i == 128 && j == 150 ? uint16_t(65535u * 550u / 600u) : 0;
}

std::vector<uint32_t> bruteForce(const Terrain& t, const scene::Frustum& frustum) {
    std::vector<uint32_t> visible;
    for (uint32_t p = 0; p < t.grid().patchCount(); ++p)
        if (frustum.classify(t.bounds().patchBounds(p)) != scene::Frustum::Containment::Outside) visible.push_back(p);
    return visible;
}

std::vector<uint32_t> cullSorted(const Terrain& t, const scene::Camera& camera) {
    std::vector<uint32_t> visible;
    t.cull(camera.frustum(), camera.position(), visible);
    std::vector<uint32_t> sorted = visible;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "a patch appears twice";
    return sorted;
}

scene::Camera makeCamera(const scene::CameraPose& pose) {
    scene::Camera camera;
    camera.setAspect(1.0f);
    camera.setPose(pose);
    return camera;
}

} // namespace

TEST(TerrainCull, LookingStraightDownSeesEveryPatchLookingUpSeesNone) {
    Terrain t(makeField(hills), 8);
    std::vector<uint32_t> all(64);
    for (uint32_t p = 0; p < 64; ++p) all[p] = p;
    EXPECT_EQ(cullSorted(t, makeCamera({{512.0f, 5000.0f, 512.0f}, 0.0f, glm::radians(-89.9f)})), all);
    EXPECT_TRUE(cullSorted(t, makeCamera({{512.0f, 5000.0f, 512.0f}, 0.0f, glm::radians(89.9f)})).empty());
    // Appending keeps what the caller already had.
    std::vector<uint32_t> visible{999};
    t.cull(makeCamera({{512.0f, 5000.0f, 512.0f}, 0.0f, glm::radians(-89.9f)}).frustum(), {512.0f, 5000.0f, 512.0f},
           visible);
    EXPECT_EQ(visible.size(), 65u);
    EXPECT_EQ(visible.front(), 999u);
}

TEST(TerrainCull, LowDownOverTheCentreSeesOnlyThePatchesBelow) {
    Terrain t(makeField(flat), 8);
    // 60 degrees of view from 100 m up: a square of about +-58 m around (512, 512),
    // the corner where patches (3..4, 3..4) meet.
    const auto visible = cullSorted(t, makeCamera({{512.0f, 100.0f, 512.0f}, 0.0f, glm::radians(-90.0f)}));
    EXPECT_EQ(visible, (std::vector<uint32_t>{27, 28, 35, 36}));
}

TEST(TerrainCull, ATallPeakKeepsItsPatchWhenTheBaseIsOutOfView) {
    // Looking 40 degrees up from 100 m: the ground is below the frustum, but
    // the spike's tip at (512, 550, 600) is in view.
    const scene::Camera camera = makeCamera({{512.0f, 100.0f, 1100.0f}, 0.0f, glm::radians(40.0f)});
    const scene::Frustum frustum = camera.frustum();
    ASSERT_TRUE(frustum.contains({512.0f, 550.0f, 600.0f}));

    Terrain ground(makeField(flat), 8);
    EXPECT_TRUE(cullSorted(ground, camera).empty());

    Terrain peaked(makeField(spike), 8);
    // Sample 128 lies on the boundary of patch columns 3 and 4; z 600 m is in row 4.
    const auto visible = cullSorted(peaked, camera);
    EXPECT_EQ(visible, (std::vector<uint32_t>{35, 36}));
    for (uint32_t p : visible) {
        scene::Aabb base = peaked.bounds().patchBounds(p);
        base.max.y = base.min.y;
        EXPECT_EQ(frustum.classify(base), scene::Frustum::Containment::Outside) << p;
    }
}

TEST(TerrainCull, MatchesBruteForceForRandomCameras) {
    for (uint32_t patchesPerSide : {8u, 5u, 13u}) {
        Terrain t(makeField(hills), patchesPerSide);
        // The core's generator: the same cameras with every standard library.
        Random random(42);
        uint32_t nonEmpty = 0, partial = 0;
        for (int trial = 0; trial < 200; ++trial) {
            const glm::vec3 position{-300.0f + 1600.0f * random.nextFloat(), 50.0f + 900.0f * random.nextFloat(),
                                     -300.0f + 1600.0f * random.nextFloat()};
            const float yaw = 6.2831853f * random.nextFloat();
            const float pitch = glm::radians(-85.0f + 100.0f * random.nextFloat());
            scene::Camera camera = makeCamera({position, yaw, pitch});
            camera.setClipPlanes(0.5f, 200.0f + 2000.0f * random.nextFloat());
            const auto visible = cullSorted(t, camera);
            EXPECT_EQ(visible, bruteForce(t, camera.frustum())) << "P " << patchesPerSide << " trial " << trial;
            nonEmpty += !visible.empty();
            partial += !visible.empty() && visible.size() < t.grid().patchCount();
        }
        // The cameras exercise both outcomes and partial views.
        EXPECT_GT(nonEmpty, 50u);
        EXPECT_GT(partial, 50u);
    }
}

TEST(TerrainCull, NearerBlocksComeFirst) {
    Terrain t(makeField(flat), 8);
    // Low over the -X,-Z corner looking along the diagonal towards +X,+Z.
    const glm::vec3 eye{-50.0f, 60.0f, -50.0f};
    const scene::Camera camera = makeCamera({eye, glm::radians(-135.0f), glm::radians(-20.0f)});
    std::vector<uint32_t> visible;
    t.cull(camera.frustum(), eye, visible);
    ASSERT_GT(visible.size(), 4u);
    EXPECT_EQ(visible.front(), 0u);
    // The same call always gives the same order.
    std::vector<uint32_t> again;
    t.cull(camera.frustum(), eye, again);
    EXPECT_EQ(visible, again);
}
