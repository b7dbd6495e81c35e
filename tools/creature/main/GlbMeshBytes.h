#pragma once
/// @file GlbMeshBytes.h
/// Measures how many bytes a .glb spends on its meshes, for Table 1.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>

namespace tessera::creature {

/// The bytes of the cage's mesh primitives' vertex attributes and indices in
/// a .glb (mesh 0; the far LOD's mesh 1 is not part of Table 1): a Draco
/// primitive counts its compressed buffer view; an
/// uncompressed one counts count x component size x components of each
/// accessor it uses.
Result<uint64_t> measureGlbMeshBytes(const std::filesystem::path& file);

} // namespace tessera::creature
