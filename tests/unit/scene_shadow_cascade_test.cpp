// The cascaded shadow map's split and fit (scene/CascadeSplits.h,
// scene/ShadowCascadeFit.h): the practical split scheme's ends and blend,
// every slice inside its cascade, casters towards the sun kept, and the
// stability the fit promises (whole-texel moves, sizes independent of the
// camera's heading).
#include "tessera/scene/Camera.h"
#include "tessera/scene/CascadeSplits.h"
#include "tessera/scene/ShadowCascadeFit.h"
#include "tessera/scene/ShadowCascadeUniforms.h"

#include <array>
#include <cmath>
#include <gtest/gtest.h>

using tessera::scene::Camera;
using tessera::scene::practicalCascadeSplits;
using tessera::scene::ShadowCascade;
using tessera::scene::ShadowCascadeFit;

namespace {

Camera makeCamera(const glm::vec3& position, float yawDegrees, float pitchDegrees) {
    Camera camera;
    camera.setPose({position, glm::radians(yawDegrees), glm::radians(pitchDegrees)});
    camera.setAspect(16.0f / 9.0f);
    return camera;
}

/// The eight corners of the view frustum's slice between two view depths.
std::array<glm::vec3, 8> sliceCorners(const Camera& camera, float nearDistance, float farDistance) {
    const float tanY = std::tan(0.5f * camera.verticalFov());
    const float tanX = tanY * camera.aspect();
    const glm::vec3 forward = camera.forward();
    const glm::vec3 right = camera.right();
    const glm::vec3 up = glm::cross(right, forward);
    std::array<glm::vec3, 8> corners{};
    int i = 0;
    for (float d : {nearDistance, farDistance}) {
        for (float sx : {-1.0f, 1.0f}) {
            for (float sy : {-1.0f, 1.0f}) {
                corners[i++] = camera.position() + forward * d + right * (sx * d * tanX) + up * (sy * d * tanY);
            }
        }
    }
    return corners;
}

glm::vec3 clip(const ShadowCascade& cascade, const glm::vec3& p) {
    const glm::vec4 c = cascade.viewProjection * glm::vec4(p, 1.0f);
    return glm::vec3(c) / c.w;
}

const glm::vec3 kLowSun = glm::normalize(glm::vec3(0.6f, 0.25f, -0.45f));

} // namespace

TEST(ScenePracticalSplits, EndsAreExactAndSplitsIncrease) {
    const std::vector<float> s = practicalCascadeSplits(0.5f, 300.0f, 4, 0.8f);
    ASSERT_EQ(s.size(), 5u);
    EXPECT_EQ(s.front(), 0.5f);
    EXPECT_EQ(s.back(), 300.0f);
    for (size_t i = 1; i < s.size(); ++i) EXPECT_GT(s[i], s[i - 1]);
}

TEST(ScenePracticalSplits, LambdaBlendsUniformAndLogarithmic) {
    const std::vector<float> uniform = practicalCascadeSplits(1.0f, 1000.0f, 3, 0.0f);
    EXPECT_NEAR(uniform[1], 334.0f, 1e-3f);
    EXPECT_NEAR(uniform[2], 667.0f, 1e-3f);
    const std::vector<float> logarithmic = practicalCascadeSplits(1.0f, 1000.0f, 3, 1.0f);
    EXPECT_NEAR(logarithmic[1], 10.0f, 1e-3f);
    EXPECT_NEAR(logarithmic[2], 100.0f, 1e-2f);
    const std::vector<float> half = practicalCascadeSplits(1.0f, 1000.0f, 3, 0.5f);
    EXPECT_NEAR(half[1], 0.5f * (10.0f + 334.0f), 1e-3f);
}

TEST(ScenePracticalSplits, OneCascadeIsTheWholeRange) {
    const std::vector<float> s = practicalCascadeSplits(2.0f, 50.0f, 1, 0.7f);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0], 2.0f);
    EXPECT_EQ(s[1], 50.0f);
}

TEST(SceneShadowCascadeFit, CascadesFollowTheSplitsAndStopAtTheShadowDistance) {
    ShadowCascadeFit::Settings settings;
    settings.shadowDistance = 250.0f;
    const ShadowCascadeFit fit(settings);
    const Camera camera = makeCamera({1800.0f, 900.0f, 6800.0f}, -30.0f, -16.0f);
    const std::vector<ShadowCascade> cascades = fit.fit(camera, kLowSun);
    ASSERT_EQ(cascades.size(), 4u);
    const std::vector<float> splits = practicalCascadeSplits(camera.nearPlane(), 250.0f, 4, settings.splitLambda);
    for (size_t i = 0; i < cascades.size(); ++i) {
        EXPECT_EQ(cascades[i].nearDistance, splits[i]);
        EXPECT_EQ(cascades[i].farDistance, splits[i + 1]);
        EXPECT_FLOAT_EQ(cascades[i].texelSize, 2.0f * cascades[i].radius / float(settings.resolution));
        if (i > 0) {
            EXPECT_GT(cascades[i].radius, cascades[i - 1].radius);
        }
    }
    EXPECT_EQ(ShadowCascadeFit::cascadeIndex(cascades, 0.5f), 0u);
    EXPECT_EQ(ShadowCascadeFit::cascadeIndex(cascades, splits[2] + 0.01f), 2u);
    EXPECT_EQ(ShadowCascadeFit::cascadeIndex(cascades, 250.0f), 3u);
    EXPECT_EQ(ShadowCascadeFit::cascadeIndex(cascades, 251.0f), 4u);
}

TEST(SceneShadowCascadeFit, EverySliceLiesInsideItsCascade) {
    const ShadowCascadeFit fit;
    for (const glm::vec3& sun : {kLowSun, glm::vec3(0.0f, 1.0f, 0.0f), glm::normalize(glm::vec3(-0.2f, 0.9f, 0.1f))}) {
        for (float yaw : {0.0f, 37.0f, 133.0f, -90.0f}) {
            for (float pitch : {-89.0f, -16.0f, 0.0f, 40.0f}) {
                const Camera camera = makeCamera({1234.5f, 420.0f, -3021.25f}, yaw, pitch);
                for (const ShadowCascade& c : fit.fit(camera, sun)) {
                    for (const glm::vec3& corner : sliceCorners(camera, c.nearDistance, c.farDistance)) {
                        const glm::vec3 p = clip(c, corner);
                        EXPECT_LE(std::abs(p.x), 1.0f + 1e-4f);
                        EXPECT_LE(std::abs(p.y), 1.0f + 1e-4f);
                        EXPECT_GE(p.z, -1e-4f);
                        EXPECT_LE(p.z, 1.0f + 1e-4f);
                    }
                }
            }
        }
    }
}

TEST(SceneShadowCascadeFit, CastersTowardsTheSunAreKeptAndNearestIsDepthZero) {
    ShadowCascadeFit::Settings settings;
    settings.casterReach = 120.0f;
    const ShadowCascadeFit fit(settings);
    const Camera camera = makeCamera({500.0f, 80.0f, 500.0f}, 20.0f, -10.0f);
    for (const ShadowCascade& c : fit.fit(camera, kLowSun)) {
        for (const glm::vec3& corner : sliceCorners(camera, c.nearDistance, c.farDistance)) {
            // A caster up the sun's ray from a receiver lands on the same
            // texel, nearer the sun (smaller depth), still inside the range.
            const glm::vec3 receiver = clip(c, corner);
            const glm::vec3 caster = clip(c, corner + kLowSun * 100.0f);
            EXPECT_NEAR(caster.x, receiver.x, 1e-4f);
            EXPECT_NEAR(caster.y, receiver.y, 1e-4f);
            EXPECT_LT(caster.z, receiver.z);
            EXPECT_GE(caster.z, -1e-4f);
        }
        EXPECT_NEAR(c.depthRange, 2.0f * c.radius + 120.0f, 1e-3f);
    }
}

TEST(SceneShadowCascadeFit, SizesDoNotChangeAsTheCameraTurnsOrMoves) {
    const ShadowCascadeFit fit;
    const std::vector<ShadowCascade> reference = fit.fit(makeCamera({0.0f, 50.0f, 0.0f}, 0.0f, 0.0f), kLowSun);
    for (float yaw : {11.0f, 95.0f, 181.0f}) {
        const std::vector<ShadowCascade> turned = fit.fit(makeCamera({77.7f, 12.0f, -9.3f}, yaw, -35.0f), kLowSun);
        for (size_t i = 0; i < reference.size(); ++i) {
            EXPECT_EQ(turned[i].radius, reference[i].radius);
            EXPECT_EQ(turned[i].texelSize, reference[i].texelSize);
        }
    }
}

TEST(SceneShadowCascadeFit, MovingTheCameraSlidesTheMapsByWholeTexels) {
    ShadowCascadeFit::Settings settings;
    settings.resolution = 512;
    const ShadowCascadeFit fit(settings);
    // A fixed world point's texel coordinate (clip xy * resolution / 2) must
    // change by whole texels only, however little the camera moved.
    const glm::vec3 probe(1500.0f, 300.0f, 6000.0f);
    const std::vector<ShadowCascade> before = fit.fit(makeCamera({1480.0f, 320.0f, 6010.0f}, 10.0f, -20.0f), kLowSun);
    for (const glm::vec3& step : {glm::vec3(0.013f, 0.0f, 0.0f), glm::vec3(0.7f, -0.2f, 3.1f),
                                  glm::vec3(-17.25f, 4.0f, 9.5f)}) {
        const std::vector<ShadowCascade> after =
            fit.fit(makeCamera(glm::vec3(1480.0f, 320.0f, 6010.0f) + step, 10.0f, -20.0f), kLowSun);
        for (size_t i = 0; i < before.size(); ++i) {
            const glm::vec2 texelsBefore = glm::vec2(clip(before[i], probe)) * (0.5f * float(settings.resolution));
            const glm::vec2 texelsAfter = glm::vec2(clip(after[i], probe)) * (0.5f * float(settings.resolution));
            const glm::vec2 moved = texelsAfter - texelsBefore;
            EXPECT_NEAR(moved.x, std::round(moved.x), 2e-2f) << "cascade " << i;
            EXPECT_NEAR(moved.y, std::round(moved.y), 2e-2f) << "cascade " << i;
        }
    }
}

TEST(SceneShadowCascadeFit, ShadowDistanceIsClampedToTheFarPlane) {
    ShadowCascadeFit::Settings settings;
    settings.shadowDistance = 5000.0f;
    settings.cascadeCount = 2;
    const ShadowCascadeFit fit(settings);
    Camera camera = makeCamera({0.0f, 10.0f, 0.0f}, 0.0f, 0.0f);
    camera.setClipPlanes(1.0f, 800.0f);
    const std::vector<ShadowCascade> cascades = fit.fit(camera, kLowSun);
    ASSERT_EQ(cascades.size(), 2u);
    EXPECT_EQ(cascades.front().nearDistance, 1.0f);
    EXPECT_EQ(cascades.back().farDistance, 800.0f);
}

TEST(SceneShadowCascadeFit, SunViewLooksAlongTheSunEvenAtTheZenith) {
    for (const glm::vec3& sun : {kLowSun, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f)}) {
        const glm::mat4 view = ShadowCascadeFit::sunView(sun);
        // The sun's direction maps to view +Z (the view looks down -Z).
        const glm::vec3 towards = glm::vec3(view * glm::vec4(sun, 0.0f));
        EXPECT_NEAR(towards.z, 1.0f, 1e-5f);
        for (int c = 0; c < 3; ++c) EXPECT_FALSE(std::isnan(view[c][0]));
    }
}

TEST(SceneShadowCascadeUniforms, PacksTheCascadesAndSelectsLikeTheFit) {
    ShadowCascadeFit::Settings settings;
    settings.cascadeCount = 3;
    const ShadowCascadeFit fit(settings);
    const std::vector<ShadowCascade> cascades = fit.fit(makeCamera({10.0f, 20.0f, 30.0f}, 45.0f, -10.0f), kLowSun);
    const tessera::shader::ShadowCascadeUniforms u = tessera::scene::buildShadowCascadeUniforms(cascades, 2048);
    EXPECT_EQ(u.params.x, 3.0f);
    EXPECT_EQ(u.params.y, 1.0f / 2048.0f);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(u.viewProjection[i], cascades[size_t(i)].viewProjection);
        EXPECT_EQ(u.farDistances[i], cascades[size_t(i)].farDistance);
        EXPECT_EQ(u.texelSizes[i], cascades[size_t(i)].texelSize);
        EXPECT_EQ(u.depthRanges[i], cascades[size_t(i)].depthRange);
    }
    // The selection the shaders run (ShadowCascades.h) is the fit's.
    for (float depth = 0.0f; depth < 320.0f; depth += 0.37f) {
        EXPECT_EQ(tessera::shader::tsShadowCascadeIndex(u.farDistances, 3u, depth),
                  ShadowCascadeFit::cascadeIndex(cascades, depth))
            << "at " << depth << " m";
    }
    const tessera::shader::ShadowCascadeUniforms none = tessera::scene::buildShadowCascadeUniforms({}, 1024);
    EXPECT_EQ(none.params.x, 0.0f);
    EXPECT_EQ(tessera::shader::tsShadowCascadeIndex(none.farDistances, 0u, 1.0f), 0u);
}

TEST(SceneShadowCascadeUniforms, CullPerCascadeKeepsEveryCasterWhoseShadowACascadeReads) {
    // Casters one metre in radius standing on flat ground (y = 0) across
    // the view: each point of a caster and of its shadow on the ground is
    // a receiver, reading the cascade its view depth selects, and that
    // cascade must draw the caster; the cull must also skip some.
    const Camera camera = makeCamera({0.0f, 30.0f, 0.0f}, 30.0f, -20.0f);
    for (const glm::vec3& sun : {kLowSun, glm::normalize(glm::vec3(0.3f, 0.85f, 0.2f))}) {
        const std::vector<ShadowCascade> cascades = ShadowCascadeFit().fit(camera, sun);
        size_t culled = 0;
        for (float x = -200.0f; x <= 200.0f; x += 7.0f) {
            for (float z = -300.0f; z <= 20.0f; z += 7.0f) {
                const glm::vec4 sphere(x, 1.0f, z, 1.0f);
                const float casterDepth = glm::dot(glm::vec3(sphere) - camera.position(), camera.forward());
                std::vector<glm::vec3> receivers;
                for (float t = 0.0f; t <= 1.0f; t += 0.125f) {
                    const glm::vec3 onBody(x, 2.0f * t, z); // the body's axis, feet to head
                    receivers.push_back(onBody);
                    receivers.push_back(onBody - sun * (onBody.y / sun.y)); // its shadow on the ground
                }
                for (size_t i = 0; i < cascades.size(); ++i) {
                    const tessera::shader::ShadowCasterPush push =
                        tessera::scene::buildShadowCasterPush(cascades, i, sun);
                    const bool outside =
                        tessera::shader::tsShadowCasterOutside(sphere, casterDepth, push.viewProjection, push.cull);
                    culled += outside ? 1 : 0;
                    if (!outside) continue;
                    for (const glm::vec3& r : receivers) {
                        const float depth = glm::dot(r - camera.position(), camera.forward());
                        const glm::vec3 c = clip(cascades[i], r);
                        const bool inSquare = std::abs(c.x) <= 1.0f && std::abs(c.y) <= 1.0f;
                        EXPECT_FALSE(ShadowCascadeFit::cascadeIndex(cascades, depth) == i && inSquare)
                            << "caster at (" << x << ", " << z << ") culled from cascade " << i
                            << " whose receiver at depth " << depth << " it shadows";
                    }
                }
            }
        }
        EXPECT_GT(culled, 0u);
    }
}

TEST(SceneShadowCascadeFit, ACpuRasterizerGetsFewerCascadesAndTaps) {
    using tessera::lod::DeviceClass;
    const ShadowCascadeFit::Settings gpu = ShadowCascadeFit::Settings::forDevice(DeviceClass::Gpu);
    const ShadowCascadeFit::Settings cpu = ShadowCascadeFit::Settings::forDevice(DeviceClass::Cpu);
    EXPECT_EQ(gpu.cascadeCount, ShadowCascadeFit::kMaxCascades);
    EXPECT_EQ(gpu.pcfTaps, 3u);
    EXPECT_LT(cpu.cascadeCount, gpu.cascadeCount);
    EXPECT_LT(cpu.pcfTaps, gpu.pcfTaps);
    EXPECT_EQ(tessera::scene::buildShadowCascadeUniforms({}, 1024, cpu.pcfTaps).pcf.x, float(cpu.pcfTaps));
}
