#pragma once
/// @file AnimationSampler.h
/// Evaluates one glTF animation channel at a time (the CPU reference of
/// character animation; Pose applies whole clips with it).

#include "tessera/character/AnimationClip.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace tessera::character {

/// The channel's value at `seconds`, clamped to its key range (before the
/// first key: the first value; after the last: the last value).
///
/// - Step: the value of the last key at or before `seconds`.
/// - Linear: component-wise lerp; for Rotation a slerp along the shorter arc
///   (the second quaternion is negated when the dot product is negative).
/// - CubicSpline: glTF's Hermite spline, tangents scaled by the key interval;
///   a Rotation result is normalised.
///
/// Rotations are returned as (x, y, z, w); translation and scale in xyz.
/// A channel with no keys, or fewer values than its keys need, yields the
/// zero vector: callers skip such channels (Pose does).
glm::vec4 sampleChannel(const AnimationChannel& channel, float seconds);

/// True when `channel` has keys and as many values as its interpolation
/// needs (one per key, or three for CubicSpline).
bool isChannelSampleable(const AnimationChannel& channel);

/// Spherical linear interpolation of unit quaternions along the shorter arc;
/// t = 0 gives `a`, t = 1 gives `b` or -b. Falls back to a normalised lerp
/// when the quaternions are nearly parallel.
glm::quat slerpShortest(const glm::quat& a, const glm::quat& b, float t);

} // namespace tessera::character
