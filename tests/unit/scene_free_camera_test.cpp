// The demo window's fly camera: keys move along the view, the mouse turns it,
// pitch is clamped, and the basis is the Camera's own.
#include "tessera/scene/Camera.h"
#include "tessera/scene/FreeCamera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace tessera::scene {
namespace {

TEST(FreeCamera, ForwardMovesAlongTheCamerasView) {
    CameraPose start{{10.0f, 5.0f, -3.0f}, 0.7f, -0.2f};
    FreeCamera fly(start, 10.0f);
    fly.update({.forward = 1.0f}, 0.5f);
    Camera camera;
    camera.setPose(start);
    const glm::vec3 expected = start.position + camera.forward() * 5.0f;
    EXPECT_NEAR(glm::length(fly.pose().position - expected), 0.0f, 1e-4f);
}

TEST(FreeCamera, StrafeIsHorizontalAndUpIsWorldUp) {
    CameraPose start{{0.0f, 0.0f, 0.0f}, 1.1f, 0.6f};
    FreeCamera fly(start, 2.0f);
    fly.update({.right = 1.0f}, 1.0f);
    Camera camera;
    camera.setPose(start);
    EXPECT_NEAR(glm::length(fly.pose().position - camera.right() * 2.0f), 0.0f, 1e-5f);
    EXPECT_FLOAT_EQ(fly.pose().position.y, 0.0f);
    fly.setPose(start);
    fly.update({.up = 1.0f}, 1.0f);
    EXPECT_NEAR(fly.pose().position.y, 2.0f, 1e-5f);
}

TEST(FreeCamera, DiagonalsAreNoFasterAndShiftIsFaster) {
    FreeCamera fly({}, 3.0f);
    fly.update({.forward = 1.0f, .right = 1.0f}, 1.0f);
    EXPECT_NEAR(glm::length(fly.pose().position), 3.0f, 1e-5f);
    fly.setPose({});
    fly.update({.forward = 1.0f, .fast = true}, 1.0f);
    EXPECT_NEAR(glm::length(fly.pose().position), 3.0f * FreeCamera::kFastFactor, 1e-4f);
}

TEST(FreeCamera, MouseTurnsAndPitchIsClamped) {
    FreeCamera fly({}, 1.0f, 0.01f);
    fly.update({.lookX = 10.0f}, 0.0f);
    EXPECT_NEAR(fly.pose().yaw, -0.1f, 1e-6f); // right turns towards +X
    Camera camera;
    camera.setPose(fly.pose());
    EXPECT_GT(camera.forward().x, 0.0f);
    fly.update({.lookY = -100000.0f}, 0.0f);
    EXPECT_FLOAT_EQ(fly.pose().pitch, FreeCamera::kMaxPitch);
    fly.update({.lookY = 100000.0f}, 0.0f);
    EXPECT_FLOAT_EQ(fly.pose().pitch, -FreeCamera::kMaxPitch);
}

} // namespace
} // namespace tessera::scene
