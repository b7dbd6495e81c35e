#pragma once
/// @file GlbMeshBytes.h
/// Measures how many bytes a .glb spends on its meshes, for Table 1.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>

namespace tessera::creature {

/// The bytes of every mesh primitive's vertex attributes and indices in a
/// .glb: a Draco primitive counts its compressed buffer view; an
/// uncompressed one counts count x component size x components of each
/// accessor it uses.
Result<uint64_t> measureGlbMeshBytes(const std::filesystem::path& file);

} // namespace tessera::creature
