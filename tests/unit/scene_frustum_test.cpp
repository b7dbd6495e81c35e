#include "tessera/scene/Camera.h"
#include "tessera/scene/Frustum.h"

#include <gtest/gtest.h>

using tessera::scene::Aabb;
using tessera::scene::Camera;
using tessera::scene::Frustum;
using Containment = tessera::scene::Frustum::Containment;

namespace {

/// Camera at the origin looking down -Z; 90 degree vertical field of view and
/// aspect 1, so the side planes are |x| = -z and |y| = -z; near 1, far 100.
Frustum makeFrustum() {
    Camera camera;
    camera.setVerticalFov(glm::radians(90.0f));
    camera.setAspect(1.0f);
    camera.setClipPlanes(1.0f, 100.0f);
    return camera.frustum();
}

Aabb cube(const glm::vec3& center, float half) {
    return Aabb::fromMinMax(center - glm::vec3(half), center + glm::vec3(half));
}

} // namespace

TEST(SceneFrustum, PlanesAreNormalizedAndPointInward) {
    Frustum f = makeFrustum();
    const glm::vec3 inside(0, 0, -50);
    for (const glm::vec4& plane : f.planes()) {
        EXPECT_NEAR(glm::length(glm::vec3(plane)), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(glm::vec3(plane), inside) + plane.w, 0.0f);
    }
    // Near plane: z = -1, normal toward -Z. Far plane: z = -100, normal toward +Z.
    EXPECT_NEAR(f.planes()[4].z, -1.0f, 1e-5f);
    EXPECT_NEAR(f.planes()[4].w, -1.0f, 1e-4f);
    EXPECT_NEAR(f.planes()[5].z, 1.0f, 1e-5f);
    EXPECT_NEAR(f.planes()[5].w, 100.0f, 1e-2f);
}

TEST(SceneFrustum, ContainsPoints) {
    Frustum f = makeFrustum();
    EXPECT_TRUE(f.contains(glm::vec3(0, 0, -10)));
    EXPECT_TRUE(f.contains(glm::vec3(9, -9, -10)));
    EXPECT_FALSE(f.contains(glm::vec3(11, 0, -10)));
    EXPECT_FALSE(f.contains(glm::vec3(0, 0, 10)));      // Behind.
    EXPECT_FALSE(f.contains(glm::vec3(0, 0, -0.5f)));   // Before near (Vulkan 0..1 depth).
    EXPECT_TRUE(f.contains(glm::vec3(0, 0, -1.01f)));
    EXPECT_TRUE(f.contains(glm::vec3(0, 0, -99.0f)));
    EXPECT_FALSE(f.contains(glm::vec3(0, 0, -101.0f))); // Past far.
}

TEST(SceneFrustum, ClassifiesBoxesAgainstEachPlane) {
    Frustum f = makeFrustum();
    EXPECT_EQ(f.classify(cube(glm::vec3(0, 0, -50), 5)), Containment::Inside);

    struct Case {
        const char* plane;
        glm::vec3 outside, straddling;
    };
    // At depth 20 the side planes are at +-20. Boxes of half size 2.
    const Case cases[] = {
        {"left", glm::vec3(-25, 0, -20), glm::vec3(-20, 0, -20)},
        {"right", glm::vec3(25, 0, -20), glm::vec3(20, 0, -20)},
        {"bottom", glm::vec3(0, -25, -20), glm::vec3(0, -20, -20)},
        {"top", glm::vec3(0, 25, -20), glm::vec3(0, 20, -20)},
        {"near", glm::vec3(0, 0, 2), glm::vec3(0, 0, -1)},
        {"far", glm::vec3(0, 0, -105), glm::vec3(0, 0, -100)},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.plane);
        EXPECT_EQ(f.classify(cube(c.outside, 2)), Containment::Outside);
        EXPECT_FALSE(f.intersects(cube(c.outside, 2)));
        EXPECT_EQ(f.classify(cube(c.straddling, 2)), Containment::Intersects);
        EXPECT_TRUE(f.intersects(cube(c.straddling, 2)));
    }
}

TEST(SceneFrustum, BoxEnclosingFrustumIntersectsAndEmptyIsOutside) {
    Frustum f = makeFrustum();
    EXPECT_EQ(f.classify(cube(glm::vec3(0), 1000)), Containment::Intersects);
    EXPECT_EQ(f.classify(Aabb::empty()), Containment::Outside);
}

TEST(SceneFrustum, FollowsCameraPose) {
    Camera camera;
    camera.setPosition(glm::vec3(100, 50, 0));
    camera.setYaw(glm::radians(90.0f)); // Looking toward -X.
    Frustum f = camera.frustum();
    EXPECT_TRUE(f.contains(glm::vec3(0, 50, 0)));
    EXPECT_FALSE(f.contains(glm::vec3(200, 50, 0)));
    EXPECT_FALSE(f.contains(glm::vec3(100, 50, -100)));
}
