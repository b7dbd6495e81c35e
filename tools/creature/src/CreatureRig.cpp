#include "CreatureRig.h"

#include <cmath>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace tessera::creature {

using character::AnimationChannel;
using character::AnimationClip;
using character::AnimationPath;

namespace {

constexpr float kTwoPi = 6.28318530718f;
constexpr float kFrameRate = 30.0f;

// Samples `angle(t)` about `axis` into a linear rotation channel over
// [0, duration] at 30 Hz. The functions are periodic, so the loop closes.
AnimationChannel rotationChannel(Joint joint, const glm::vec3& axis, float duration,
                                 const std::function<float(float)>& angle) {
    AnimationChannel ch;
    ch.node = static_cast<uint32_t>(joint);
    ch.path = AnimationPath::Rotation;
    int frames = static_cast<int>(std::lround(duration * kFrameRate));
    for (int i = 0; i <= frames; ++i) {
        float t = static_cast<float>(i) / kFrameRate;
        glm::quat q = glm::angleAxis(angle(t), glm::normalize(axis));
        ch.times.push_back(t);
        ch.values.emplace_back(q.x, q.y, q.z, q.w);
    }
    return ch;
}

AnimationChannel translationChannel(Joint joint, const glm::vec3& rest, float duration,
                                    const std::function<glm::vec3(float)>& offset) {
    AnimationChannel ch;
    ch.node = static_cast<uint32_t>(joint);
    ch.path = AnimationPath::Translation;
    int frames = static_cast<int>(std::lround(duration * kFrameRate));
    for (int i = 0; i <= frames; ++i) {
        float t = static_cast<float>(i) / kFrameRate;
        ch.times.push_back(t);
        ch.values.emplace_back(rest + offset(t), 0.0f);
    }
    return ch;
}

glm::vec3 restTranslation(const CreatureParams& c, Joint j) {
    Joint parent = jointParent(j);
    return parent == Joint::Count ? c.at(j) : c.at(j) - c.at(parent);
}

} // namespace

character::Skeleton makeSkeleton(const CreatureParams& c) {
    character::Skeleton skeleton;
    for (uint32_t j = 0; j < kJointCount; ++j) {
        character::SkeletonNode node;
        node.name = jointName(static_cast<Joint>(j));
        Joint parent = jointParent(static_cast<Joint>(j));
        node.parent = parent == Joint::Count ? -1 : static_cast<int32_t>(parent);
        node.rest.translation = restTranslation(c, static_cast<Joint>(j));
        skeleton.nodes.push_back(node);
    }
    return skeleton;
}

std::vector<character::SkinBinding> makeBindings(const character::Skeleton& skeleton) {
    std::vector<glm::mat4> global(skeleton.nodes.size());
    std::vector<character::SkinBinding> bindings;
    for (size_t i = 0; i < skeleton.nodes.size(); ++i) {
        const auto& node = skeleton.nodes[i];
        glm::mat4 local = node.rest.matrix();
        global[i] = node.parent < 0 ? local : global[static_cast<size_t>(node.parent)] * local;
        bindings.push_back({static_cast<uint32_t>(i), glm::inverse(global[i])});
    }
    return bindings;
}

AnimationClip makeWalkClip(const CreatureParams& c) {
    const float T = 1.1f;
    auto phase = [T](float t) { return kTwoPi * t / T; };
    const glm::vec3 X(1, 0, 0), Y(0, 1, 0);
    AnimationClip clip;
    clip.name = "walk";
    // Two bobs per stride: lowest when the legs are furthest apart.
    clip.channels.push_back(translationChannel(Joint::Hips, restTranslation(c, Joint::Hips), T, [&](float t) {
        return glm::vec3(0.0f, 0.018f * std::cos(2.0f * phase(t)) - 0.01f, 0.0f);
    }));
    clip.channels.push_back(rotationChannel(Joint::Hips, Y, T, [&](float t) { return 0.1f * std::sin(phase(t)); }));
    clip.channels.push_back(rotationChannel(Joint::Spine, Y, T, [&](float t) { return -0.07f * std::sin(phase(t)); }));
    clip.channels.push_back(rotationChannel(Joint::Head, X, T, [&](float t) { return 0.05f * std::sin(2.0f * phase(t)); }));
    for (int side = 0; side < 2; ++side) {
        // The right side runs half a stride behind the left.
        float sign = side == 0 ? 1.0f : -1.0f;
        Joint thigh = side == 0 ? Joint::ThighL : Joint::ThighR, shin = side == 0 ? Joint::ShinL : Joint::ShinR;
        Joint foot = side == 0 ? Joint::FootL : Joint::FootR;
        Joint upper = side == 0 ? Joint::UpperArmL : Joint::UpperArmR;
        Joint fore = side == 0 ? Joint::ForearmL : Joint::ForearmR;
        auto swing = [=](float t) { return -0.45f * sign * std::sin(phase(t)); };  // negative: leg forward
        auto bend = [=](float t) {
            float lift = 0.5f + 0.5f * sign * std::cos(phase(t));  // 1 while the leg swings forward
            return 0.1f + 0.6f * lift * lift;
        };
        clip.channels.push_back(rotationChannel(thigh, X, T, swing));
        clip.channels.push_back(rotationChannel(shin, X, T, bend));
        // Keep the sole roughly level with the ground.
        clip.channels.push_back(rotationChannel(foot, X, T, [=](float t) { return -0.8f * (swing(t) + bend(t)) + 0.08f; }));
        clip.channels.push_back(rotationChannel(upper, X, T, [=](float t) { return 0.35f * sign * std::sin(phase(t)); }));
        clip.channels.push_back(rotationChannel(fore, X, T, [=](float t) {
            return -0.2f - 0.15f * (0.5f - 0.5f * sign * std::sin(phase(t)));
        }));
    }
    return clip;
}

AnimationClip makeIdleClip(const CreatureParams& c) {
    const float T = 3.0f;
    auto phase = [T](float t) { return kTwoPi * t / T; };
    const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
    AnimationClip clip;
    clip.name = "idle";
    clip.channels.push_back(translationChannel(Joint::Hips, restTranslation(c, Joint::Hips), T, [&](float t) {
        return glm::vec3(0.0f, 0.006f * std::sin(2.0f * phase(t)), 0.0f);
    }));
    // Breathing: the chest lifts twice per loop.
    clip.channels.push_back(rotationChannel(Joint::Chest, X, T, [&](float t) { return -0.04f * std::sin(2.0f * phase(t)); }));
    clip.channels.push_back(rotationChannel(Joint::Head, Y, T, [&](float t) { return 0.35f * std::sin(phase(t)); }));
    // A quick twitch, one ear at a time; a Gaussian pulse is ~0 at the ends.
    auto twitch = [](float t, float at) { float x = (t - at) / 0.09f; return 0.3f * std::exp(-x * x); };
    clip.channels.push_back(rotationChannel(Joint::EarL, Z, T, [&](float t) { return twitch(t, 0.9f); }));
    clip.channels.push_back(rotationChannel(Joint::EarR, Z, T, [&](float t) { return -twitch(t, 2.1f); }));
    for (Joint arm : {Joint::UpperArmL, Joint::UpperArmR}) {
        float sign = arm == Joint::UpperArmL ? 1.0f : -1.0f;
        clip.channels.push_back(rotationChannel(arm, X, T, [=](float t) { return 0.05f * sign * std::sin(phase(t)); }));
    }
    return clip;
}

} // namespace tessera::creature
