#include "creature/CreatureParams.h"

#include "tessera/core/Random.h"

#include <cmath>

namespace tessera::creature {

namespace {

constexpr const char* kNames[kJointCount] = {
    "root", "hips", "spine", "chest", "neck", "head", "jaw", "ear_l", "ear_r",
    "shoulder_l", "upper_arm_l", "forearm_l", "hand_l",
    "shoulder_r", "upper_arm_r", "forearm_r", "hand_r",
    "thigh_l", "shin_l", "foot_l", "thigh_r", "shin_r", "foot_r"};

constexpr Joint kParents[kJointCount] = {
    Joint::Count, Joint::Root, Joint::Hips, Joint::Spine, Joint::Chest, Joint::Neck, Joint::Head,
    Joint::Head, Joint::Head,
    Joint::Chest, Joint::ShoulderL, Joint::UpperArmL, Joint::ForearmL,
    Joint::Chest, Joint::ShoulderR, Joint::UpperArmR, Joint::ForearmR,
    Joint::Hips, Joint::ThighL, Joint::ShinL, Joint::Hips, Joint::ThighR, Joint::ShinR};

glm::vec3 mirror(const glm::vec3& v) { return {-v.x, v.y, v.z}; }

} // namespace

const char* jointName(Joint joint) { return kNames[static_cast<uint32_t>(joint)]; }

Joint jointParent(Joint joint) { return kParents[static_cast<uint32_t>(joint)]; }

CreatureParams makeCreatureParams(uint32_t seed) {
    // One stream per creature; the draw order below is part of the format:
    // append new draws at the end so old seeds keep their shapes.
    Random rng(seed, 0x46726F626C696EULL);
    CreatureParams c;
    c.seed = seed;
    c.hipHeight = rng.range(0.33f, 0.42f);
    c.hunch = rng.range(0.45f, 0.8f);
    c.torsoLength = rng.range(0.3f, 0.38f);
    c.bellyRadius = rng.range(0.16f, 0.22f);
    c.chestRadius = rng.range(0.15f, 0.19f);
    c.headRadius = rng.range(0.15f, 0.185f);
    c.earLength = rng.range(0.16f, 0.28f);
    c.earLift = rng.range(-0.1f, 0.6f);
    c.earSweep = rng.range(0.1f, 0.6f);
    c.earWidth = rng.range(0.045f, 0.065f);
    c.noseLength = rng.range(0.06f, 0.12f);
    c.jawSize = rng.range(0.075f, 0.1f);
    c.armLength = rng.range(0.55f, 0.68f);
    c.limbThickness = rng.range(0.85f, 1.2f);
    c.footLength = rng.range(0.17f, 0.22f);
    c.skinHue = rng.range(-1.0f, 1.0f);
    c.eyeRadius = rng.range(0.021f, 0.026f);
    c.lidDroop = rng.range(0.05f, 0.4f);
    c.irisHue = rng.range(0.0f, 1.0f);
    c.mouthWidth = rng.range(0.038f, 0.052f);
    c.grin = rng.range(0.0f, 1.0f);
    c.toothCount = 4u + static_cast<uint32_t>(rng.range(0.0f, 2.999f));
    c.tuskLength = rng.range(0.014f, 0.026f);
    c.leatherHue = rng.range(0.0f, 1.0f);
    // Every creature wears the belt; the outfit cycles with the seed
    // (strap and bracers, strap only, bracers only, belt only), so any
    // four neighbouring seeds, and the crowd's seeds 1 to 3, all differ.
    // Seed 1, the docs' close-up, wears everything.
    const uint32_t outfit = seed % 4u;
    c.chestStrap = outfit == 1u || outfit == 2u;
    c.bracers = outfit == 1u || outfit == 3u;

    auto set = [&c](Joint j, const glm::vec3& p) { c.joints[static_cast<uint32_t>(j)] = p; };
    auto setTip = [&c](Joint j, const glm::vec3& p) { c.tips[static_cast<uint32_t>(j)] = p; };
    set(Joint::Root, {0.0f, 0.0f, 0.0f});
    glm::vec3 hips(0.0f, c.hipHeight, 0.0f);
    set(Joint::Hips, hips);
    glm::vec3 spine = hips + glm::vec3(0.0f, 0.1f, 0.0f);
    set(Joint::Spine, spine);
    glm::vec3 chest = spine + c.torsoLength * glm::vec3(0.0f, std::cos(c.hunch), std::sin(c.hunch));
    set(Joint::Chest, chest);
    // The hunch carries the head forward and the neck juts out of the chest.
    glm::vec3 neck = chest + glm::vec3(0.0f, 0.09f, 0.06f + 0.05f * c.hunch);
    set(Joint::Neck, neck);
    glm::vec3 head = neck + glm::vec3(0.0f, 0.06f + c.headRadius * 0.5f, 0.07f);
    set(Joint::Head, head);
    glm::vec3 jaw = head + glm::vec3(0.0f, -0.04f, 0.04f);
    set(Joint::Jaw, jaw);
    glm::vec3 earBase = head + glm::vec3(c.headRadius * 0.82f, 0.02f, -0.02f);
    set(Joint::EarL, earBase);
    set(Joint::EarR, mirror(earBase));
    glm::vec3 earDir = glm::normalize(glm::vec3(std::cos(c.earLift), std::sin(c.earLift), -std::sin(c.earSweep)));
    glm::vec3 earTip = earBase + c.earLength * earDir;

    glm::vec3 shoulder = chest + glm::vec3(0.06f, 0.01f, -0.03f);
    glm::vec3 upperArm = chest + glm::vec3(c.chestRadius + 0.04f, -0.01f, -0.03f);
    float upperLen = c.armLength * 0.5f, foreLen = c.armLength * 0.5f;
    glm::vec3 elbow = upperArm + upperLen * glm::normalize(glm::vec3(0.38f, -1.0f, 0.05f));
    glm::vec3 wrist = elbow + foreLen * glm::normalize(glm::vec3(0.12f, -1.0f, 0.3f));
    glm::vec3 handTip = wrist + 0.13f * glm::normalize(glm::vec3(0.04f, -1.0f, 0.3f));
    set(Joint::ShoulderL, shoulder);
    set(Joint::UpperArmL, upperArm);
    set(Joint::ForearmL, elbow);
    set(Joint::HandL, wrist);
    set(Joint::ShoulderR, mirror(shoulder));
    set(Joint::UpperArmR, mirror(upperArm));
    set(Joint::ForearmR, mirror(elbow));
    set(Joint::HandR, mirror(wrist));

    // Short bent legs: the knee sits forward of the hip and the ankle.
    const float ankleHeight = 0.07f;
    glm::vec3 thigh = hips + glm::vec3(0.1f, -0.03f, 0.0f);
    float drop = thigh.y - ankleHeight;
    glm::vec3 knee = thigh + glm::vec3(0.025f, -drop * 0.5f, 0.12f);
    glm::vec3 ankle(0.125f, ankleHeight, -0.02f);
    glm::vec3 toe = ankle + glm::vec3(0.01f, -0.03f, c.footLength);
    set(Joint::ThighL, thigh);
    set(Joint::ShinL, knee);
    set(Joint::FootL, ankle);
    set(Joint::ThighR, mirror(thigh));
    set(Joint::ShinR, mirror(knee));
    set(Joint::FootR, mirror(ankle));

    // A bone's far end is its first child, or the tips above for the leaves.
    c.tips = c.joints;
    for (uint32_t j = kJointCount; j-- > 1;) {
        Joint parent = kParents[j];
        if (parent != Joint::Count && parent != Joint::Head) c.tips[static_cast<uint32_t>(parent)] = c.joints[j];
    }
    setTip(Joint::Root, hips);
    setTip(Joint::Head, head + glm::vec3(0.0f, c.headRadius, 0.0f));
    setTip(Joint::Neck, head);
    setTip(Joint::Jaw, jaw + glm::vec3(0.0f, -0.06f, 0.05f + c.jawSize * 0.5f));
    setTip(Joint::EarL, earTip);
    setTip(Joint::EarR, mirror(earTip));
    setTip(Joint::HandL, handTip);
    setTip(Joint::HandR, mirror(handTip));
    setTip(Joint::FootL, toe);
    setTip(Joint::FootR, mirror(toe));
    setTip(Joint::Hips, spine);
    setTip(Joint::Chest, neck);
    return c;
}

} // namespace tessera::creature
