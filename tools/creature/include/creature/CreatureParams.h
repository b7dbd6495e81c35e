#pragma once
/// @file CreatureParams.h
/// The proportions of one creature, drawn from its seed, and the bind-pose
/// joint positions they imply (metres, +Y up, facing +Z, feet at y = 0).

#include <array>
#include <cstdint>
#include <glm/glm.hpp>

namespace tessera::creature {

/// The skeleton's joints, parents before children. Left is +X (the
/// creature's own left when it faces +Z).
enum class Joint : uint32_t {
    Root, Hips, Spine, Chest, Neck, Head, Jaw, EarL, EarR,
    ShoulderL, UpperArmL, ForearmL, HandL,
    ShoulderR, UpperArmR, ForearmR, HandR,
    ThighL, ShinL, FootL, ThighR, ShinR, FootR,
    Count
};

/// Number of joints.
inline constexpr uint32_t kJointCount = static_cast<uint32_t>(Joint::Count);

/// The glTF node name of a joint ("hips", "ear_l", ...).
const char* jointName(Joint joint);
/// The parent of a joint, or Joint::Count for the root.
Joint jointParent(Joint joint);

/// Proportions (metres, radians) and the joint positions they give.
struct CreatureParams {
    uint32_t seed = 1;
    float hipHeight = 0.42f;    ///< hips above the ground
    float hunch = 0.45f;        ///< forward lean of the chest from vertical
    float torsoLength = 0.36f;  ///< spine to chest
    float bellyRadius = 0.2f;   ///< the pot belly
    float chestRadius = 0.17f;
    float headRadius = 0.15f;
    float earLength = 0.22f;
    float earLift = 0.25f;      ///< ear elevation above horizontal
    float earSweep = 0.35f;     ///< ear tilt backwards
    float earWidth = 0.06f;     ///< ear base half-height
    float noseLength = 0.09f;
    float jawSize = 0.09f;
    float armLength = 0.62f;    ///< shoulder to wrist
    float limbThickness = 1.0f; ///< multiplies every limb radius
    float footLength = 0.2f;
    float skinHue = 0.0f;       ///< -1..1, shifts the palette between olive and grey-green

    // Close-up features (docs/CHARACTERS.md, "Face and gear"): drawn after
    // the proportions above, so adding them kept every seed's body.
    float eyeRadius = 0.023f;   ///< eyeball radius
    float lidDroop = 0.2f;      ///< upper lid edge above the eye centre, in eye radii (lower: sleepier)
    float irisHue = 0.5f;       ///< 0..1, iris from sulphur yellow through amber to blood red
    float mouthWidth = 0.045f;  ///< half-width of the lip line
    float grin = 0.5f;          ///< 0..1, how far the mouth corners turn up
    uint32_t toothCount = 5;    ///< pointed upper teeth along the lip line
    float tuskLength = 0.02f;   ///< the two lower tusks, from the lower lip up
    float leatherHue = 0.5f;    ///< 0..1, the gear's leather from tan to dark oxblood
    bool chestStrap = true;     ///< a leather strap from the left shoulder to the right hip (seeds 1, 2 mod 4)
    bool bracers = true;        ///< leather bracers on both forearms (seeds 1, 3 mod 4)
    /// Bind-pose positions of the joints, indexed by Joint.
    std::array<glm::vec3, kJointCount> joints{};
    /// Ends of the bones that have no child joint (head top, ear tips,
    /// finger tips, toes, jaw chin), indexed by Joint; equal to the joint
    /// itself elsewhere.
    std::array<glm::vec3, kJointCount> tips{};

    const glm::vec3& at(Joint j) const { return joints[static_cast<uint32_t>(j)]; }
    const glm::vec3& tip(Joint j) const { return tips[static_cast<uint32_t>(j)]; }
};

/// Draws the proportions for `seed` and places the joints. Deterministic.
CreatureParams makeCreatureParams(uint32_t seed);

} // namespace tessera::creature
