#pragma once
// LodReader: the far LOD mesh a file stores with MSFT_lod. The character's
// mesh node names its lower levels in extensions.MSFT_lod.ids; the lowest
// (the last id) is the far tier's mesh. It must be a mesh node skinned by the
// same skin as the mesh node (or, for a rigid mesh, unskinned), so the cage's
// palette poses it. Throws GltfError naming the JSON pointer and the problem.

#include "SkeletonBuilder.h"
#include "tessera/character/CageMesh.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace tessera::assets {

/// Checks every MSFT_lod of the scene's mesh nodes and returns the far mesh
/// when the scene has exactly one mesh node and it has lower levels. With
/// several mesh nodes the cage merges them all and no single level stands
/// for the whole character: nullopt (the loader simplifies the cage instead).
std::optional<character::CageMesh> readFarLod(const tinygltf::Model& model, const nlohmann::json& json,
                                              const SkeletonBuild& skeleton, const character::CageMesh& cage);

} // namespace tessera::assets
