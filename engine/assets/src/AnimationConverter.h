#pragma once
// AnimationConverter: glTF animations into clips over skeleton indices.
// Translation, rotation and scale channels are kept; morph 'weights' and
// KHR_animation_pointer channels are skipped (morph targets are not supported).

#include "AccessorReader.h"
#include "SkeletonBuilder.h"
#include "tessera/character/AnimationClip.h"

namespace tessera::assets {

std::vector<character::AnimationClip> convertAnimations(const tinygltf::Model& model, const SkeletonBuild& skeleton);

} // namespace tessera::assets
