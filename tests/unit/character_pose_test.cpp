// CPU character animation: channel sampling against hand-computed values,
// looping, global composition, the skinning palette, linear blend skinning
// and the animated compression box.
#include "tessera/character/AnimatedBounds.h"
#include "tessera/character/AnimationSampler.h"
#include "tessera/character/CompressionError.h"
#include "tessera/character/Pose.h"
#include "tessera/character/SkinnedVertex.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

using namespace tessera;
using namespace tessera::character;

namespace {

constexpr float kEps = 1e-5f;

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

AnimationChannel translationChannel(AnimationInterpolation interpolation) {
    AnimationChannel c;
    c.path = AnimationPath::Translation;
    c.interpolation = interpolation;
    c.times = {0.0f, 1.0f, 2.0f};
    c.values = {{0, 0, 0, 0}, {1, 2, 3, 0}, {5, 5, 5, 0}};
    return c;
}

glm::vec4 quatValue(const glm::quat& q) {
    return {q.x, q.y, q.z, q.w};
}

glm::quat aboutZ(float degrees) {
    return glm::angleAxis(glm::radians(degrees), glm::vec3(0, 0, 1));
}

// Root -> child -> grandchild; the cage's vertices bind to the child.
CharacterAsset swingingArm() {
    CharacterAsset c;
    c.skeleton.nodes = {{"root", -1, {}}, {"arm", 0, {}}, {"hand", 1, {}}};
    c.skeleton.nodes[1].rest.translation = {0.0f, 1.0f, 0.0f};
    c.skeleton.nodes[2].rest.translation = {2.0f, 0.0f, 0.0f};
    c.cage.bindings = {{1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -1.0f, 0.0f))}};
    for (float x : {0.5f, 1.0f, 2.0f}) {
        CageVertex v;
        v.position = {x, 1.0f, 0.0f};
        c.cage.vertices.push_back(v);
    }
    AnimationClip swing;
    swing.name = "swing";
    AnimationChannel rotation;
    rotation.node = 1;
    rotation.path = AnimationPath::Rotation;
    rotation.times = {0.0f, 0.5f, 1.0f};
    rotation.values = {quatValue(aboutZ(0.0f)), quatValue(aboutZ(90.0f)), quatValue(aboutZ(179.0f))};
    swing.channels.push_back(rotation);
    c.clips.push_back(swing);
    return c;
}

} // namespace

TEST(AnimationSampler, StepHoldsTheLastKey) {
    const AnimationChannel c = translationChannel(AnimationInterpolation::Step);
    expectVec(sampleChannel(c, -1.0f), {0, 0, 0});
    expectVec(sampleChannel(c, 0.5f), {0, 0, 0});
    expectVec(sampleChannel(c, 1.0f), {1, 2, 3});
    expectVec(sampleChannel(c, 1.99f), {1, 2, 3});
    expectVec(sampleChannel(c, 3.0f), {5, 5, 5});
    expectVec(sampleChannel(c, std::nanf("")), {0, 0, 0});
}

TEST(AnimationSampler, LinearInterpolatesComponents) {
    const AnimationChannel c = translationChannel(AnimationInterpolation::Linear);
    expectVec(sampleChannel(c, 0.25f), {0.25f, 0.5f, 0.75f});
    expectVec(sampleChannel(c, 1.5f), {3.0f, 3.5f, 4.0f});
    expectVec(sampleChannel(c, 2.0f), {5, 5, 5});
}

TEST(AnimationSampler, CubicSplineScalesTangentsByTheKeyInterval) {
    AnimationChannel c;
    c.interpolation = AnimationInterpolation::CubicSpline;
    c.times = {0.0f, 2.0f};
    // (in-tangent, value, out-tangent) per key.
    c.values = {{9, 9, 9, 0}, {0, 0, 0, 0}, {1, 0, 0, 0}, {0, 2, 0, 0}, {1, 1, 1, 0}, {9, 9, 9, 0}};
    // At s = 0.5: h00 = h01 = 0.5, h10 = 0.125, h11 = -0.125, interval 2:
    // 0.5 * 0 + 0.25 * (1,0,0) + 0.5 * (1,1,1) - 0.25 * (0,2,0).
    expectVec(sampleChannel(c, 1.0f), {0.75f, 0.0f, 0.5f});
    expectVec(sampleChannel(c, 0.0f), {0, 0, 0});
    expectVec(sampleChannel(c, 2.0f), {1, 1, 1});
    // At s = 0.25: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = -0.046875.
    expectVec(sampleChannel(c, 0.5f), {0.28125f + 0.15625f, 0.15625f - 0.1875f, 0.15625f});
}

TEST(AnimationSampler, CubicRotationIsNormalised) {
    AnimationChannel c;
    c.path = AnimationPath::Rotation;
    c.interpolation = AnimationInterpolation::CubicSpline;
    c.times = {0.0f, 1.0f};
    c.values = {{0, 0, 0, 0}, quatValue(aboutZ(0.0f)),  {0, 0, 0, 0},
                {0, 0, 0, 0}, quatValue(aboutZ(90.0f)), {0, 0, 0, 0}};
    const glm::vec4 q = sampleChannel(c, 0.5f);
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
    // Zero tangents and symmetric ends: the midpoint lies halfway in angle.
    EXPECT_NEAR(q.z / q.w, std::tan(glm::radians(22.5f)), 1e-5f);
}

TEST(AnimationSampler, LinearRotationTakesTheShortestPath) {
    AnimationChannel c;
    c.path = AnimationPath::Rotation;
    c.times = {0.0f, 1.0f};
    // The second key is 90 degrees about z written as the negated quaternion:
    // a naive slerp would turn 270 degrees the other way.
    c.values = {quatValue(aboutZ(0.0f)), -quatValue(aboutZ(90.0f))};
    const glm::vec4 v = sampleChannel(c, 0.5f);
    const glm::quat q(v.w, v.x, v.y, v.z);
    expectVec(q * glm::vec3(1, 0, 0), {std::sqrt(0.5f), std::sqrt(0.5f), 0.0f});
    const glm::quat third = slerpShortest(aboutZ(0.0f), aboutZ(90.0f), 1.0f / 3.0f);
    expectVec(third * glm::vec3(1, 0, 0), {std::cos(glm::radians(30.0f)), std::sin(glm::radians(30.0f)), 0.0f});
}

TEST(AnimationSampler, UnusableChannelsAreReported) {
    AnimationChannel c = translationChannel(AnimationInterpolation::CubicSpline);
    EXPECT_FALSE(isChannelSampleable(c)); // cubic needs three values per key
    c.times.clear();
    EXPECT_FALSE(isChannelSampleable(c));
    EXPECT_TRUE(isChannelSampleable(translationChannel(AnimationInterpolation::Linear)));
}

TEST(Pose, LoopsAndClampsClipTime) {
    Skeleton skeleton;
    skeleton.nodes = {{"n", -1, {}}};
    AnimationClip clip;
    clip.channels.push_back(translationChannel(AnimationInterpolation::Linear));
    Pose pose(skeleton);
    pose.apply(clip, 2.5f); // wraps to 0.5
    expectVec(pose.locals()[0].translation, {0.5f, 1.0f, 1.5f});
    pose.apply(clip, -0.5f); // wraps to 1.5
    expectVec(pose.locals()[0].translation, {3.0f, 3.5f, 4.0f});
    pose.apply(clip, 2.5f, false); // clamps to the end
    expectVec(pose.locals()[0].translation, {5, 5, 5});
    pose.reset();
    expectVec(pose.locals()[0].translation, {0, 0, 0});
    // A channel naming a node the skeleton lacks is skipped.
    clip.channels[0].node = 7;
    pose.apply(clip, 1.0f);
    expectVec(pose.locals()[0].translation, {0, 0, 0});
}

TEST(Pose, ComposesGlobalsParentFirst) {
    Skeleton skeleton;
    skeleton.nodes = {{"root", -1, {}}, {"child", 0, {}}, {"grandchild", 1, {}}};
    skeleton.nodes[0].rest.translation = {1, 0, 0};
    skeleton.nodes[1].rest.translation = {0, 1, 0};
    skeleton.nodes[1].rest.rotation = aboutZ(90.0f);
    skeleton.nodes[2].rest.translation = {1, 0, 0};
    skeleton.nodes[2].rest.scale = {2, 2, 2};
    Pose pose(skeleton);
    // (1,0,0) + (0,1,0) + R90z * (1,0,0) = (1,2,0).
    expectVec(glm::vec3(pose.globals()[2][3]), {1, 2, 0});
    // The grandchild's x axis: rotated to +y and scaled by 2.
    expectVec(glm::vec3(pose.globals()[2][0]), {0, 2, 0});
    pose.local(0).translation = {0, 0, 5};
    pose.computeGlobals();
    expectVec(glm::vec3(pose.globals()[2][3]), {0, 2, 5});
}

TEST(Pose, PaletteIsGlobalTimesInverseBind) {
    const CharacterAsset arm = swingingArm();
    Pose pose(arm.skeleton);
    std::vector<glm::mat4> palette;
    pose.palette(arm.cage, palette);
    ASSERT_EQ(palette.size(), 1u);
    // At rest the bind pose is the rest pose: identity palette.
    for (int c = 0; c < 4; ++c) expectVec(glm::vec3(palette[0][c]), glm::vec3(glm::mat4(1.0f)[c]));
    pose.apply(arm.clips[0], 0.5f);
    pose.computeGlobals();
    pose.palette(arm.cage, palette);
    const glm::mat4 expected = pose.globals()[1] * arm.cage.bindings[0].inverseBind;
    for (int c = 0; c < 4; ++c) expectVec(glm::vec3(palette[0][c]), glm::vec3(expected[c]));
    // The vertex at (2,1,0) swings 90 degrees about the arm's origin (0,1,0).
    expectVec(skinVertex(arm.cage.vertices[2], palette).position, {0, 3, 0});
}

TEST(SkinVertex, BlendsOneToFourWeights) {
    const std::vector<glm::mat4> palette = {glm::translate(glm::mat4(1.0f), {4, 0, 0}),
                                            glm::translate(glm::mat4(1.0f), {0, 8, 0}),
                                            glm::translate(glm::mat4(1.0f), {0, 0, 12}), glm::mat4_cast(aboutZ(90.0f))};
    CageVertex v;
    v.position = {1, 0, 0};
    v.joints = {0, 1, 2, 3};
    v.weights = {1, 0, 0, 0};
    expectVec(skinVertex(v, palette).position, {5, 0, 0});
    v.weights = {0.5f, 0.5f, 0, 0};
    expectVec(skinVertex(v, palette).position, {3, 4, 0});
    v.weights = {0.25f, 0.25f, 0.5f, 0};
    expectVec(skinVertex(v, palette).position, {2, 2, 6});
    v.weights = {0.25f, 0.25f, 0.25f, 0.25f};
    expectVec(skinVertex(v, palette).position, {1.75f, 2.25f, 3.0f}); // (5,0,0) (1,8,0) (1,0,12) (0,1,0)
    // One rigid rotation: normal and tangent rotate, the sign survives.
    v.weights = {0, 0, 0, 1};
    v.normal = {1, 0, 0};
    v.tangent = {0, 0, 1, -1};
    const SkinnedVertex s = skinVertex(v, palette);
    expectVec(s.normal, {0, 1, 0});
    expectVec(glm::vec3(s.tangent), {0, 0, 1});
    EXPECT_EQ(s.tangent.w, -1.0f);
    // Weights not summing to one are renormalised; all zero keeps the bind pose.
    v.weights = {2, 2, 0, 0};
    expectVec(skinVertex(v, palette).position, {3, 4, 0});
    v.weights = {0, 0, 0, 0};
    expectVec(skinVertex(v, palette).position, {1, 0, 0});
}

TEST(SkinVertex, NonUniformScaleUsesTheInverseTranspose) {
    const std::vector<glm::mat4> palette = {glm::scale(glm::mat4(1.0f), {2, 1, 1})};
    CageVertex v;
    v.normal = glm::normalize(glm::vec3(1, 1, 0));
    v.tangent = glm::vec4(glm::normalize(glm::vec3(1, -1, 0)), 1.0f);
    const SkinnedVertex s = skinVertex(v, palette);
    expectVec(s.normal, glm::normalize(glm::vec3(0.5f, 1, 0)));
    expectVec(glm::vec3(s.tangent), glm::normalize(glm::vec3(2, -1, 0)));
    EXPECT_NEAR(glm::dot(s.normal, glm::vec3(s.tangent)), 0.0f, 1e-6f);
    // A mirroring bone keeps the normal outward (the cofactor's sign fixed).
    const std::vector<glm::mat4> mirror = {glm::scale(glm::mat4(1.0f), {-1, 1, 1})};
    v.normal = {1, 0, 0};
    expectVec(skinVertex(v, mirror).normal, {-1, 0, 0});
}

TEST(AnimatedBounds, ContainsEverySampledPose) {
    const CharacterAsset arm = swingingArm();
    const scene::Aabb tight = animatedBounds(arm, 32, 0.0f);
    const scene::Aabb padded = animatedBounds(arm);
    Pose pose(arm.skeleton);
    std::vector<glm::mat4> palette;
    for (int s = 0; s <= 31; ++s) {
        pose.reset();
        pose.apply(arm.clips[0], float(s) / 31.0f, false);
        pose.computeGlobals();
        pose.palette(arm.cage, palette);
        for (const CageVertex& v : arm.cage.vertices) EXPECT_TRUE(tight.contains(skinVertex(v, palette).position));
    }
    // Between the samples the padded box still holds the swing.
    for (int s = 0; s <= 1000; ++s) {
        pose.reset();
        pose.apply(arm.clips[0], float(s) / 1000.0f, false);
        pose.computeGlobals();
        pose.palette(arm.cage, palette);
        for (const CageVertex& v : arm.cage.vertices) EXPECT_TRUE(padded.contains(skinVertex(v, palette).position));
    }
    // The swing reaches (0,3,0) at t = 0.5, between two of the 32 samples
    // (k / 31): the unpadded box falls just short, as documented.
    EXPECT_LT(tight.max.y, 3.0f);
    EXPECT_GT(tight.max.y, 2.99f);
    EXPECT_TRUE(padded.contains({0.0f, 3.0f, 0.0f}));
    // Near 179 degrees the hand vertex is close to (-2,1,0).
    EXPECT_LT(tight.min.x, -1.99f);
    EXPECT_NEAR(padded.max.y - tight.max.y, 0.05f * (tight.max.x - tight.min.x), 1e-5f);
    EXPECT_TRUE(animatedBounds(CharacterAsset{}).isEmpty());
}

TEST(AnimatedBounds, AnimatedCompressionErrorStaysInsideThePaddedBox) {
    const CharacterAsset arm = swingingArm();
    const scene::Aabb box = animatedBounds(arm);
    const CompressionErrorStats stats = measureAnimatedCompressionError(arm, box, uvBounds(arm.cage.vertices), 16);
    EXPECT_EQ(stats.vertexCount, 3u * (1u + 16u));
    // Every skinned sample is inside the box: no clamping, only the
    // quantisation (half a 16-bit step per axis, relative to the extent).
    EXPECT_LE(stats.maxPositionError, std::sqrt(3.0) * 0.5 / 65535.0 + 1e-6);
    EXPECT_LT(stats.maxNormalAngleDeg, 0.07);
}
