#pragma once
/// @file GltfLoader.h
/// Loads any glTF 2.0 file (.gltf with external or embedded buffers, .glb,
/// KHR_draco_mesh_compression) into a character::CharacterAsset.

#include "tessera/character/CharacterAsset.h"
#include "tessera/core/Result.h"

#include <filesystem>

namespace tessera::assets {

/// Loads the default scene of a glTF 2.0 file as one character: every
/// triangle primitive of every mesh node becomes part of the cage (skinned
/// meshes keep their skins; rigid meshes bind to their own node), every node
/// becomes a skeleton node, every animation a clip. Textures are decoded.
/// On failure the error names the file and the problem in one line
/// ("CesiumMan.gltf: accessor 3: byte range 0..4096 exceeds buffer view 2 (2048 bytes)").
Result<character::CharacterAsset> loadCharacter(const std::filesystem::path& file);

} // namespace tessera::assets
