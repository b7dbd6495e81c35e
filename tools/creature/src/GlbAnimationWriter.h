#pragma once
/// @file GlbAnimationWriter.h
/// Writes animation clips as glTF animations.

#include "GlbBuilder.h"
#include "tessera/character/AnimationClip.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace tessera::creature {

/// Adds one glTF animation per clip that has channels (glTF forbids empty
/// animations) and returns the `animations` array, or an empty array.
/// Each channel gets a sampler; its input accessor (key times, with the
/// min/max glTF requires) is shared by every channel with the same times.
/// Node indices are the skeleton's. Clips are assumed checked
/// (checkCharacter).
nlohmann::json writeAnimations(GlbBuilder& glb, const std::vector<character::AnimationClip>& clips);

} // namespace tessera::creature
