#pragma once
/// @file GlbAssetCheck.h
/// The checks a character must pass before it is written as glTF.

#include "tessera/character/CharacterAsset.h"
#include "tessera/core/Result.h"

#include <string>

namespace tessera::creature {

/// Fails, naming `file` and the first problem, when `asset` would make an
/// invalid glTF file: an empty or out-of-range cage, non-finite numbers,
/// joints beyond the skin's palette, nodes out of parent-first order,
/// animation keys that are not strictly increasing non-negative times (or
/// whose value count does not match), maps of the wrong format.
Status checkCharacter(const character::CharacterAsset& asset, const std::string& file);

} // namespace tessera::creature
