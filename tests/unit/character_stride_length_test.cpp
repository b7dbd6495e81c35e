// Stride length from a walk clip (character::measureStride) on synthetic
// bipeds whose stride is known exactly: in place, with root motion, in
// centimetres under a scaled and turned root, with unnamed feet; and the
// cases that must give 0 (an idle, a march on the spot, no feet).
#include "tessera/character/StrideLength.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <string>

using namespace tessera;
using namespace tessera::character;

namespace {

constexpr float kPi = 3.14159265358979f;

// The scripted walk: a 1 s cycle. Each foot is planted for 60% of it and
// slides back under the hips from +0.36 m to -0.36 m (1.2 m/s), then swings
// forward in 0.4 s, lifting 0.1 m. The right foot runs half a cycle behind.
// Stride: 1.2 m per cycle, natural speed 1.2 m/s.
constexpr float kCycle = 1.0f;
constexpr float kStance = 0.6f;
constexpr float kHalfStep = 0.36f;
constexpr float kLift = 0.1f;
constexpr float kExpectedStride = 2.0f * kHalfStep / kStance * kCycle; // 1.2

// Foot offset (x unused, y lift, z forward) at phase p in [0, 1).
glm::vec3 footOffset(float p) {
    if (p < kStance) return {0.0f, 0.0f, kHalfStep - 2.0f * kHalfStep * p / kStance};
    const float u = (p - kStance) / (1.0f - kStance);
    return {0.0f, kLift * std::sin(kPi * u), -kHalfStep + 2.0f * kHalfStep * u};
}

struct RigOptions {
    std::string footLeft = "foot_l", footRight = "foot_r";
    bool toes = false;                        ///< a toe joint under each foot
    float unit = 1.0f;                        ///< model units per metre (100: centimetres)
    glm::quat facing{1.0f, 0.0f, 0.0f, 0.0f}; ///< the root's rotation
    bool rootMotion = false;                  ///< the hips travel forward at the walking speed
    bool march = false;                       ///< lift the feet but keep them under the hips
    bool backwards = false;                   ///< walk backwards (the feet slide forward in stance)
};

enum Node : uint32_t { Armature, Hips, ThighL, FootL, ThighR, FootR, Spine, HandL, HandR, Head, ToeL, ToeR };

SkeletonNode node(const char* name, int32_t parent, const glm::vec3& t) {
    SkeletonNode n;
    n.name = name;
    n.parent = parent;
    n.rest.translation = t;
    return n;
}

AnimationChannel translation(uint32_t target, const std::function<glm::vec3(float)>& at, float duration) {
    AnimationChannel c;
    c.node = target;
    c.path = AnimationPath::Translation;
    const int keys = 60 * static_cast<int>(std::lround(duration));
    for (int k = 0; k <= keys; ++k) {
        const float t = duration * static_cast<float>(k) / static_cast<float>(keys);
        c.times.push_back(t);
        c.values.emplace_back(at(t), 0.0f);
    }
    return c;
}

// A biped 1.1 m tall at the hips: hips 1 m up, feet 0.1 m up at rest (the
// ankle), arms and a head above, all under an "Armature" root.
CharacterAsset biped(const RigOptions& o) {
    const float u = o.unit;
    CharacterAsset a;
    a.name = "biped";
    a.skeleton.nodes = {
        node("Armature", -1, {0, 0, 0}),
        node("hips", Armature, glm::vec3(0.0f, 1.0f, 0.0f) * u),
        node("thigh_l", Hips, glm::vec3(0.1f, -0.1f, 0.0f) * u),
        node(o.footLeft.c_str(), ThighL, glm::vec3(0.0f, -0.8f, 0.0f) * u),
        node("thigh_r", Hips, glm::vec3(-0.1f, -0.1f, 0.0f) * u),
        node(o.footRight.c_str(), ThighR, glm::vec3(0.0f, -0.8f, 0.0f) * u),
        node("spine", Hips, glm::vec3(0.0f, 0.3f, 0.0f) * u),
        node("hand_l", Spine, glm::vec3(0.3f, 0.0f, 0.0f) * u),
        node("hand_r", Spine, glm::vec3(-0.3f, 0.0f, 0.0f) * u),
        node("head", Spine, glm::vec3(0.0f, 0.4f, 0.0f) * u),
    };
    if (o.toes) {
        a.skeleton.nodes.push_back(node("toe_l", FootL, glm::vec3(0.0f, -0.08f, 0.15f) * u));
        a.skeleton.nodes.push_back(node("toe_r", FootR, glm::vec3(0.0f, -0.08f, 0.15f) * u));
    }
    a.skeleton.nodes[Armature].rest.rotation = o.facing;
    a.skeleton.nodes[Armature].rest.scale = glm::vec3(1.0f / u);

    AnimationClip walk;
    walk.name = "walk";
    for (int side = 0; side < 2; ++side) {
        const float shift = side == 0 ? 0.0f : 0.5f;
        walk.channels.push_back(translation(
            side == 0 ? FootL : FootR,
            [=](float t) {
                float p = t / kCycle + shift;
                p -= std::floor(p);
                glm::vec3 offset = footOffset(p);
                if (o.march) offset.z = 0.0f;
                if (o.backwards) offset.z = -offset.z;
                return (glm::vec3(0.0f, -0.8f, 0.0f) + offset) * u;
            },
            kCycle));
    }
    if (o.rootMotion)
        walk.channels.push_back(translation(
            Hips, [=](float t) { return glm::vec3(0.0f, 1.0f, kExpectedStride / kCycle * t) * u; }, kCycle));
    a.clips.push_back(walk);

    // An idle: the hips breathe up and down, the arms sway; the feet stay.
    AnimationClip idle;
    idle.name = "idle";
    idle.channels.push_back(translation(
        Hips, [=](float t) { return glm::vec3(0.0f, 1.0f + 0.01f * std::sin(kPi * t), 0.0f) * u; }, 2.0f));
    idle.channels.push_back(translation(
        HandL, [=](float t) { return glm::vec3(0.3f, 0.0f, 0.05f * std::sin(kPi * t)) * u; }, 2.0f));
    a.clips.push_back(idle);
    return a;
}

void expectStride(const StrideMeasure& m, float stride, float duration) {
    EXPECT_NEAR(m.strideLength, stride, 0.02f * stride);
    EXPECT_NEAR(m.naturalSpeed, m.strideLength / duration, 1e-5f * stride);
}

} // namespace

TEST(StrideLength, ScriptedWalkInPlace) {
    const CharacterAsset a = biped({});
    const StrideMeasure m = measureStride(a, 0);
    expectStride(m, kExpectedStride, kCycle);
    EXPECT_EQ(m.feet, (std::vector<uint32_t>{FootL, FootR}));
    std::printf("scripted walk: stride %.4f m (exact %.4f), natural speed %.4f m/s\n", m.strideLength, kExpectedStride,
                m.naturalSpeed);
}

TEST(StrideLength, RootMotionGivesTheSameStride) {
    RigOptions o;
    o.rootMotion = true;
    const StrideMeasure m = measureStride(biped(o), 0);
    expectStride(m, kExpectedStride, kCycle);
}

TEST(StrideLength, CentimetreSkeletonUnderAScaledTurnedRootIsInWorldUnits) {
    // Authored in centimetres, facing +X: the root scales by 0.01 and turns
    // +Z to +X, as exporters' armature nodes do.
    RigOptions o;
    o.unit = 100.0f;
    o.facing = glm::angleAxis(0.5f * kPi, glm::vec3(0, 1, 0));
    o.rootMotion = true;
    expectStride(measureStride(biped(o), 0), kExpectedStride, kCycle);
}

TEST(StrideLength, WalkingBackwardsHasTheSameStride) {
    // Forward is measured, not assumed: here it is -Z.
    RigOptions o;
    o.backwards = true;
    expectStride(measureStride(biped(o), 0), kExpectedStride, kCycle);
}

TEST(StrideLength, FewerSamplesStillMeasure) {
    const CharacterAsset a = biped({});
    expectStride(measureStride(a, 0, 30), kExpectedStride, kCycle);
    EXPECT_GT(measureStride(a, 0, 0).strideLength, 0.0f); // clamped to the minimum
}

TEST(StrideLength, AnkleWinsOverToe) {
    RigOptions o;
    o.toes = true;
    const StrideMeasure m = measureStride(biped(o), 0);
    EXPECT_EQ(m.feet, (std::vector<uint32_t>{FootL, FootR}));
    expectStride(m, kExpectedStride, kCycle);
}

TEST(StrideLength, UnnamedFeetAreTheLowestLeavesOnTwoLegs) {
    RigOptions o;
    o.footLeft = "leg_end.L";
    o.footRight = "leg_end.R";
    StrideMeasure m = measureStride(biped(o), 0);
    EXPECT_EQ(m.feet, (std::vector<uint32_t>{FootL, FootR}));
    expectStride(m, kExpectedStride, kCycle);

    // With toes, the leaves are the toes: they move with the feet.
    o.toes = true;
    m = measureStride(biped(o), 0);
    EXPECT_EQ(m.feet, (std::vector<uint32_t>{ToeL, ToeR}));
    expectStride(m, kExpectedStride, kCycle);
}

TEST(StrideLength, OnlySkinJointsCanBeFeet) {
    // A low helper node named like a foot that the skin does not bind (an IK
    // target) is not a foot.
    CharacterAsset a = biped({});
    a.skeleton.nodes.push_back(node("foot_ik_target", Armature, {0.5f, 0.0f, 0.0f}));
    for (uint32_t i = 0; i + 1 < a.skeleton.nodes.size(); ++i) a.cage.bindings.push_back({i, glm::mat4(1.0f)});
    const StrideMeasure m = measureStride(a, 0);
    EXPECT_EQ(m.feet, (std::vector<uint32_t>{FootL, FootR}));
    expectStride(m, kExpectedStride, kCycle);
}

TEST(StrideLength, IdleDoesNotWalk) {
    const StrideMeasure m = measureStride(biped({}), 1);
    EXPECT_EQ(m.strideLength, 0.0f);
    EXPECT_EQ(m.naturalSpeed, 0.0f);
    EXPECT_EQ(m.feet, (std::vector<uint32_t>{FootL, FootR}));
}

TEST(StrideLength, MarchingOnTheSpotDoesNotWalk) {
    RigOptions o;
    o.march = true;
    EXPECT_EQ(measureStride(biped(o), 0).strideLength, 0.0f);
}

TEST(StrideLength, NoFeetGivesZero) {
    // A snake: one chain, nothing to pair, nothing named like a foot.
    CharacterAsset snake;
    snake.skeleton.nodes = {node("root", -1, {0, 0.1f, 0}), node("spine", 0, {0, 0, 0.5f}),
                            node("neck", 1, {0, 0, 0.5f}), node("head", 2, {0, 0.05f, 0.2f})};
    AnimationClip slither;
    slither.channels.push_back(translation(
        1, [](float t) { return glm::vec3(0.2f * std::sin(2 * kPi * t), 0, 0.5f); }, 1.0f));
    snake.clips.push_back(slither);
    StrideMeasure m = measureStride(snake, 0);
    EXPECT_EQ(m.strideLength, 0.0f);
    EXPECT_TRUE(m.feet.empty());

    CharacterAsset single;
    single.skeleton.nodes = {node("foot", -1, {0, 0, 0})};
    single.clips.push_back(slither);
    m = measureStride(single, 0);
    EXPECT_EQ(m.strideLength, 0.0f);
    EXPECT_TRUE(m.feet.empty());

    EXPECT_TRUE(measureStride(CharacterAsset{}, 0).feet.empty());
}

TEST(StrideLength, BadClipIndexOrEmptyClipGivesZero) {
    CharacterAsset a = biped({});
    EXPECT_EQ(measureStride(a, 7).strideLength, 0.0f);
    a.clips.push_back({});
    const StrideMeasure m = measureStride(a, 2);
    EXPECT_EQ(m.strideLength, 0.0f);
    EXPECT_EQ(m.feet.size(), 2u);
}
