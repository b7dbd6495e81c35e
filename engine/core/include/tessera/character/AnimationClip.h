#pragma once
/// @file AnimationClip.h
/// Keyframed animation of skeleton nodes, as glTF 2.0 animations.

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace tessera::character {

/// Which part of a node's local transform a channel drives.
enum class AnimationPath : uint8_t { Translation, Rotation, Scale };

/// How values between keys are found (glTF sampler interpolation).
enum class AnimationInterpolation : uint8_t { Step, Linear, CubicSpline };

/// One animated property of one node.
///
/// `values` holds vec3s (translation, scale; w unused) or quaternions as
/// (x, y, z, w) for rotation. For Step and Linear there is one value per key;
/// for CubicSpline three per key, in glTF's order: in-tangent, value,
/// out-tangent.
struct AnimationChannel {
    uint32_t node = 0;
    AnimationPath path = AnimationPath::Translation;
    AnimationInterpolation interpolation = AnimationInterpolation::Linear;
    std::vector<float> times;       ///< strictly increasing, seconds
    std::vector<glm::vec4> values;  ///< see above
};

/// A named animation (a walk cycle, an idle). Looping is the player's choice.
struct AnimationClip {
    std::string name;
    std::vector<AnimationChannel> channels;
    /// The last key time over all channels (seconds); 0 for an empty clip.
    float duration() const;
};

} // namespace tessera::character
