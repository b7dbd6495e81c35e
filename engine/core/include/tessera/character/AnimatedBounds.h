#pragma once
/// @file AnimatedBounds.h
/// The box a character's cage sweeps while it animates: the compression box
/// of the 128-bit vertex format (CompressedVertex.h).

#include "tessera/character/CharacterAsset.h"
#include "tessera/scene/Aabb.h"

#include <cstdint>

namespace tessera::character {

/// The box of the skinned cage positions over the rest pose and every clip,
/// each sampled at `samplesPerClip` uniformly spaced times from 0 to its
/// duration inclusive (no looping), then grown on every side by `margin`
/// times the box's largest extent.
///
/// The unpadded box is exact only at the samples: between them a limb can
/// swing slightly further, and a position outside the compression box clamps
/// to its face. The margin (default 5%) covers that. Empty for an empty cage.
scene::Aabb animatedBounds(const CharacterAsset& character, uint32_t samplesPerClip = 32, float margin = 0.05f);

} // namespace tessera::character
