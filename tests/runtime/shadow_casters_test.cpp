// The characters' shadow region and casters: the square lies ahead of the
// camera with the camera inside it, and the nearest casters are kept.
#include "world/ShadowCasters.h"

#include <gtest/gtest.h>

namespace tessera::runtime {
namespace {

TEST(ShadowCasters, RegionLiesAheadOfTheCameraWithTheCameraInside) {
    scene::Camera camera;
    camera.setPose({{100.0f, 20.0f, 50.0f}, 0.0f, -0.3f}); // looking down -Z
    const glm::vec3 region = shadowRegionFor(camera);
    EXPECT_FLOAT_EQ(region.z, kShadowRegionSide);
    EXPECT_TRUE(insideRegion(region, camera.position()));
    EXPECT_TRUE(insideRegion(region, camera.position() + glm::vec3(0.0f, 0.0f, -0.8f * kShadowRegionSide)));
    EXPECT_FALSE(insideRegion(region, camera.position() + glm::vec3(0.0f, 0.0f, 0.2f * kShadowRegionSide)));
}

TEST(ShadowCasters, KeepsTheNearestToTheCentre) {
    const glm::vec3 region(0.0f, 0.0f, 100.0f);
    std::vector<glm::vec4> casters = {{90, 0, 90, 1}, {50, 0, 50, 1}, {10, 0, 10, 1}, {52, 0, 49, 1}};
    keepNearest(region, 2, casters);
    ASSERT_EQ(casters.size(), 2u);
    for (const auto& c : casters) EXPECT_NEAR(c.x, 51.0f, 1.5f);
    keepNearest(region, 5, casters);
    EXPECT_EQ(casters.size(), 2u);
}

} // namespace
} // namespace tessera::runtime
