#pragma once
/// @file LodSettings.h
/// The LOD manager's policy for a run: the device class's defaults with the
/// --lod-* flags over them.

#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"
#include "tessera/lod/LodPolicy.h"

namespace tessera::runtime {

/// For measurements (--character-level, the characters benchmark): every
/// character in view tessellated, no budget, no cross-fades.
lod::LodPolicy measureEveryCharacter();

/// lod::LodPolicy::forDevice(device), or measureEveryCharacter() when
/// --character-level forces the level, with the options' thresholds and
/// budgets over it (parseCommandLine has checked them); an error naming the
/// setting when the policy does not validate.
Result<lod::LodPolicy> lodPolicyFor(const Options& options, lod::DeviceClass device);

} // namespace tessera::runtime
