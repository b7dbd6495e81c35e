#pragma once
/// @file GlbDracoEncoder.h
/// Compresses a cage with Draco for KHR_draco_mesh_compression.

#include "creature/GlbExporter.h"
#include "tessera/character/CageMesh.h"
#include "tessera/core/Result.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tessera::creature {

/// A Draco-compressed triangle primitive and what its glTF accessors must
/// declare. Draco may reorder (and merge identical) vertices, so the counts
/// and the POSITION bounds come from decoding the compressed bytes again,
/// as the extension's implementation note asks: the accessors then match
/// exactly what every decoder produces.
struct DracoPrimitive {
    std::vector<uint8_t> bytes;
    /// glTF attribute semantic ("POSITION", "JOINTS_0", ...) to Draco unique id.
    std::map<std::string, uint32_t> attributeIds;
    uint32_t vertexCount = 0;
    uint32_t indexCount = 0;
    glm::vec3 positionMin{0.0f};
    glm::vec3 positionMax{0.0f};
    bool joints16 = false;  ///< JOINTS_0 holds uint16 (else uint8)
};

/// Encodes the cage's triangles and its POSITION, NORMAL, TANGENT,
/// TEXCOORD_0 and, when `skinned`, JOINTS_0 and WEIGHTS_0 (uint8 joints when
/// `cage.bindings` has fewer than 256 entries), with the quantisation bits
/// of `options`. Errors name `file`.
Result<DracoPrimitive> encodeDraco(const character::CageMesh& cage, bool skinned, const ExportOptions& options,
                                   const std::string& file);

} // namespace tessera::creature
