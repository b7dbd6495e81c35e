#pragma once
/// @file LodSettings.h
/// The LOD manager's policy for a run: the device class's defaults with the
/// --lod-* flags over them.

#include "DemoOptions.h"
#include "tessera/core/Result.h"
#include "tessera/lod/LodPolicy.h"

namespace tessera::demo {

/// For measurements (--character-level, the characters benchmark): every
/// character in view tessellated, no budget, no cross-fades.
lod::LodPolicy measureEveryCharacter();

/// lod::LodPolicy::forDevice(device), or measureEveryCharacter() when
/// --character-level forces the level, with the options' thresholds and
/// budgets over it (parseDemoOptions has checked them); an error naming the
/// setting when the policy does not validate.
Result<lod::LodPolicy> lodPolicyFor(const DemoOptions& options, lod::DeviceClass device);

} // namespace tessera::demo
