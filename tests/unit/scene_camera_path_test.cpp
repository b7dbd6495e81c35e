#include "tessera/scene/CameraPath.h"

#include <cmath>
#include <gtest/gtest.h>

using tessera::scene::CameraPath;
using tessera::scene::CameraPathSettings;
using tessera::scene::CameraPose;

namespace {

/// Rolling hills up to ~120 m with short, steep bumps on top.
float bumpyGround(float x, float z) {
    return 60.0f + 40.0f * std::sin(x * 0.004f) * std::cos(z * 0.003f) +
           20.0f * std::sin(x * 0.031f + 1.0f) * std::sin(z * 0.027f) +
           8.0f * std::sin(x * 0.11f) * std::cos(z * 0.13f + 0.5f);
}

CameraPathSettings makeSettings(uint32_t seed) {
    CameraPathSettings settings;
    settings.seed = seed;
    settings.regionMin = glm::vec2(-1500.0f, 200.0f);
    settings.regionMax = glm::vec2(2500.0f, 3200.0f);
    return settings;
}

bool samePose(const CameraPose& a, const CameraPose& b) {
    return a.position == b.position && a.yaw == b.yaw && a.pitch == b.pitch;
}

} // namespace

TEST(SceneCameraPath, SameSeedGivesIdenticalPoses) {
    CameraPath a(makeSettings(7), bumpyGround);
    CameraPath b(makeSettings(7), bumpyGround);
    EXPECT_EQ(a.period(), b.period());
    for (double t = -3.0; t < a.period() * 1.5; t += 0.37) {
        EXPECT_TRUE(samePose(a.sample(t), b.sample(t))) << "t = " << t;
        EXPECT_TRUE(samePose(a.sample(t), a.sample(t)));
    }
}

TEST(SceneCameraPath, DifferentSeedsDiffer) {
    CameraPath a(makeSettings(1), bumpyGround);
    CameraPath b(makeSettings(2), bumpyGround);
    EXPECT_NE(a.period(), b.period());
    EXPECT_GT(glm::distance(a.sample(5.0).position, b.sample(5.0).position), 1.0f);
}

TEST(SceneCameraPath, StaysInsideRegionAndAboveGround) {
    for (uint32_t seed = 1; seed <= 40; ++seed) {
        for (int controlPoints : {4, 8, 13}) {
            CameraPathSettings settings = makeSettings(seed);
            settings.controlPoints = controlPoints;
            CameraPath path(settings, bumpyGround);
            const int samples = 4000;
            float lowest = 1e30f;
            for (int i = 0; i < samples; ++i) {
                const CameraPose pose = path.sample(path.period() * i / samples);
                const glm::vec2 xz(pose.position.x, pose.position.z);
                ASSERT_GE(xz.x, settings.regionMin.x) << "seed " << seed;
                ASSERT_GE(xz.y, settings.regionMin.y) << "seed " << seed;
                ASSERT_LE(xz.x, settings.regionMax.x) << "seed " << seed;
                ASSERT_LE(xz.y, settings.regionMax.y) << "seed " << seed;
                lowest = std::min(lowest, pose.position.y - bumpyGround(xz.x, xz.y));
            }
            EXPECT_GE(lowest, settings.clearance * 0.5f) << "seed " << seed;
        }
    }
}

TEST(SceneCameraPath, AboveGroundEverywhereOnDenseSampling) {
    CameraPathSettings settings = makeSettings(3);
    CameraPath path(settings, bumpyGround);
    // ~0.25 m steps, far finer than the path's own ground stations.
    const int samples = static_cast<int>(path.length() * 4.0);
    for (int i = 0; i < samples; ++i) {
        const CameraPose pose = path.sample(path.period() * i / samples);
        ASSERT_GE(pose.position.y - bumpyGround(pose.position.x, pose.position.z),
                  settings.clearance * 0.5f);
    }
}

TEST(SceneCameraPath, FliesAtSteadySpeedAndLooksAheadAndDown) {
    CameraPathSettings settings = makeSettings(11);
    CameraPath path(settings, bumpyGround);
    EXPECT_NEAR(path.period(), path.length() / settings.speed, 1e-9);
    const double dt = 0.1;
    for (double t = 0.0; t < path.period(); t += 1.3) {
        const CameraPose a = path.sample(t);
        const CameraPose b = path.sample(t + dt);
        const glm::vec2 step(b.position.x - a.position.x, b.position.z - a.position.z);
        // Horizontal speed within 2% of the setting.
        EXPECT_NEAR(glm::length(step) / dt, settings.speed, settings.speed * 0.02) << "t = " << t;
        // Heading matches the direction of travel.
        const glm::vec2 forward(-std::sin(a.yaw), -std::cos(a.yaw));
        EXPECT_GT(glm::dot(glm::normalize(step), forward), 0.99f) << "t = " << t;
        // Looking down, but not at the ground beneath.
        EXPECT_LT(a.pitch, 0.0f);
        EXPECT_GT(a.pitch, glm::radians(-45.0f));
    }
}

TEST(SceneCameraPath, IsPeriodic) {
    CameraPath path(makeSettings(5), bumpyGround);
    const double period = path.period();
    for (double t : {0.0, 1.0, 17.5, period * 0.5}) {
        for (double k : {-1.0, 1.0, 3.0}) {
            const CameraPose a = path.sample(t);
            const CameraPose b = path.sample(t + k * period);
            EXPECT_LT(glm::distance(a.position, b.position), 1e-3f) << "t = " << t;
            EXPECT_NEAR(a.yaw, b.yaw, 1e-4f);
            EXPECT_NEAR(a.pitch, b.pitch, 1e-4f);
        }
    }
    // Continuous across the wrap: the end of the loop meets its start.
    const CameraPose end = path.sample(period - 1e-3);
    const CameraPose start = path.sample(0.0);
    EXPECT_LT(glm::distance(end.position, start.position), 0.1f);
}

TEST(SceneCameraPath, FlatGroundWithoutFunction) {
    CameraPathSettings settings = makeSettings(9);
    CameraPath path(settings, nullptr);
    for (double t = 0.0; t < path.period(); t += 2.0) {
        EXPECT_NEAR(path.sample(t).position.y, settings.clearance, 1e-3f);
    }
}
