#pragma once
// The creature's skeleton, skin palette and animation clips (internal header).

#include "creature/CreatureParams.h"
#include "tessera/character/AnimationClip.h"
#include "tessera/character/CageMesh.h"
#include "tessera/character/Skeleton.h"

#include <vector>

namespace tessera::creature {

/// One node per Joint (same order, parents first), rest rotations identity
/// and translations from parent to child joint.
character::Skeleton makeSkeleton(const CreatureParams& params);

/// One binding per node: palette index i binds node i with the inverse of
/// its bind-pose global matrix.
std::vector<character::SkinBinding> makeBindings(const character::Skeleton& skeleton);

/// "walk": an in-place 1.1 s loop (legs swing, knees bend, arms
/// counter-swing, hips bob and twist, head bobs), keys at 30 Hz.
character::AnimationClip makeWalkClip(const CreatureParams& params);

/// "idle": a 3 s loop (breathing, a head turn, an ear twitch each side).
character::AnimationClip makeIdleClip(const CreatureParams& params);

} // namespace tessera::creature
