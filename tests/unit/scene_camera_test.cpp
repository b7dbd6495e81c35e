#include "tessera/scene/Camera.h"

#include <cmath>
#include <gtest/gtest.h>

using tessera::scene::Camera;
using tessera::scene::CameraPose;

namespace {

glm::vec3 toNdc(const glm::mat4& viewProj, const glm::vec3& world) {
    glm::vec4 clip = viewProj * glm::vec4(world, 1.0f);
    return glm::vec3(clip) / clip.w;
}

void expectVecNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

Camera makeCamera() {
    Camera camera;
    camera.setPose(CameraPose{glm::vec3(100, 20, -40), glm::radians(30.0f), glm::radians(-10.0f)});
    return camera;
}

} // namespace

TEST(SceneCamera, Defaults) {
    Camera camera;
    EXPECT_NEAR(camera.verticalFov(), glm::radians(60.0f), 1e-6f);
    EXPECT_EQ(camera.nearPlane(), 0.5f);
    EXPECT_EQ(camera.farPlane(), 20000.0f);
    expectVecNear(camera.forward(), glm::vec3(0, 0, -1));
    expectVecNear(camera.right(), glm::vec3(1, 0, 0));
}

TEST(SceneCamera, YawAndPitchConventions) {
    Camera camera;
    camera.setYaw(glm::radians(90.0f));
    expectVecNear(camera.forward(), glm::vec3(-1, 0, 0)); // Positive yaw turns toward -X.
    camera.setYaw(0.0f);
    camera.setPitch(glm::radians(30.0f));
    EXPECT_GT(camera.forward().y, 0.0f); // Positive pitch looks up.
    EXPECT_NEAR(glm::length(camera.forward()), 1.0f, 1e-6f);
}

TEST(SceneCamera, PointStraightAheadProjectsToCenter) {
    Camera camera = makeCamera();
    const glm::mat4 viewProj = camera.viewProjection();
    for (float distance : {1.0f, 10.0f, 1000.0f, 19000.0f}) {
        glm::vec3 ndc = toNdc(viewProj, camera.position() + camera.forward() * distance);
        EXPECT_NEAR(ndc.x, 0.0f, 1e-4f);
        EXPECT_NEAR(ndc.y, 0.0f, 1e-4f);
        EXPECT_GT(ndc.z, 0.0f);
        EXPECT_LT(ndc.z, 1.0f);
    }
    // Depth 0 at the near plane, 1 at the far plane (Vulkan), not -1..1.
    EXPECT_NEAR(toNdc(viewProj, camera.position() + camera.forward() * 0.5f).z, 0.0f, 1e-4f);
    EXPECT_NEAR(toNdc(viewProj, camera.position() + camera.forward() * 20000.0f).z, 1.0f, 1e-4f);
}

TEST(SceneCamera, UpIsNegativeNdcYAndRightIsPositiveNdcX) {
    Camera camera = makeCamera();
    const glm::mat4 viewProj = camera.viewProjection();
    const glm::vec3 target = camera.position() + camera.forward() * 50.0f;
    // Vulkan's framebuffer y grows downward, so "above" is negative NDC y.
    EXPECT_LT(toNdc(viewProj, target + glm::vec3(0, 5, 0)).y, -0.01f);
    EXPECT_GT(toNdc(viewProj, target - glm::vec3(0, 5, 0)).y, 0.01f);
    EXPECT_GT(toNdc(viewProj, target + camera.right() * 5.0f).x, 0.01f);
    EXPECT_LT(camera.projection()[1][1], 0.0f);
}

TEST(SceneCamera, ViewIsInverseOfCameraPlacement) {
    Camera camera = makeCamera();
    const glm::mat4 view = camera.view();
    expectVecNear(glm::vec3(view * glm::vec4(camera.position(), 1.0f)), glm::vec3(0), 1e-4f);
    // Forward maps to view-space -Z.
    expectVecNear(glm::vec3(view * glm::vec4(camera.forward(), 0.0f)), glm::vec3(0, 0, -1));
    // Straight down is well defined (no lookAt degeneracy).
    camera.setPitch(glm::radians(-90.0f));
    expectVecNear(camera.forward(), glm::vec3(0, -1, 0));
    const glm::mat4 down = camera.view();
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(down[c][r]));
    }
}

TEST(SceneCamera, PoseRoundTrips) {
    Camera camera = makeCamera();
    CameraPose pose = camera.pose();
    EXPECT_EQ(pose.position, glm::vec3(100, 20, -40));
    EXPECT_EQ(pose.yaw, glm::radians(30.0f));
    EXPECT_EQ(pose.pitch, glm::radians(-10.0f));
}
