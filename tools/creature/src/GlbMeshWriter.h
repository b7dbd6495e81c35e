#pragma once
/// @file GlbMeshWriter.h
/// Writes the cage as one glTF triangle primitive, plain or Draco-compressed.

#include "GlbBuilder.h"
#include "creature/GlbExporter.h"
#include "tessera/character/CageMesh.h"
#include "tessera/core/Result.h"

#include <nlohmann/json.hpp>

#include <string>

namespace tessera::creature {

/// Adds the cage's data to `glb` and returns the primitive's JSON (mode
/// TRIANGLES, material 0). Attributes: POSITION (with min/max), NORMAL,
/// TANGENT, TEXCOORD_0 and, when `skinned`, JOINTS_0 (uint8 below 256
/// bindings, else uint16) and WEIGHTS_0; indices are uint16 when every
/// index fits below the primitive-restart value 65535, else uint32. Joint
/// slots of zero weight are written as joint 0, as glTF recommends.
///
/// With `options.draco` the geometry lives in one KHR_draco_mesh_compression
/// buffer view and the accessors declare count, type and (for POSITION)
/// bounds without a bufferView, as that extension requires. Otherwise each
/// attribute gets its own tightly packed buffer view. Errors name `file`.
Result<nlohmann::json> writePrimitive(GlbBuilder& glb, const character::CageMesh& cage, bool skinned,
                                      const ExportOptions& options, const std::string& file);

} // namespace tessera::creature
