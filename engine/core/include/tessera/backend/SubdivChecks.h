#pragma once
/// @file SubdivChecks.h
/// The checks every backend runs on a subdivision surface before it
/// touches a device, so bad input gets the same one-line message on every
/// backend (bgfx's validation catalogue).

#include "tessera/backend/SubdivDesc.h"
#include "tessera/core/Result.h"

#include <string>

namespace tessera::backend {

/// createSubdiv's input: a surface with faces, and tiles that are either
/// absent or one record per ptex face over a texture of the size given.
inline Status checkSubdivDesc(const SubdivDesc& desc) {
    if (!desc.mesh) return fail("createSubdiv: no surface given");
    const SubdivMeshData& mesh = *desc.mesh;
    if (mesh.baseVertexCount == 0 || mesh.domains.empty()) return fail("createSubdiv: ", mesh.name, " has no faces");
    const SubdivTileData& tiles = desc.tiles;
    if (tiles.texels.empty()) return {};
    if (tiles.records.size() != mesh.ptexFaceCount)
        return fail("createSubdiv: ", mesh.name, " has ", std::to_string(mesh.ptexFaceCount),
                    " ptex faces but its displacement has ", std::to_string(tiles.records.size()), " tile records");
    if (uint64_t(tiles.width) * tiles.height != tiles.texels.size())
        return fail("createSubdiv: ", mesh.name, "'s displacement texture holds ", std::to_string(tiles.texels.size()),
                    " texels, not ", std::to_string(tiles.width), " x ", std::to_string(tiles.height));
    return {};
}

/// updateSubdivTiles' rectangles lie inside a texture of `width` x `height`.
inline bool subdivTileRectValid(const glm::uvec4& rect, uint32_t width, uint32_t height) {
    return rect.z > 0 && rect.w > 0 && uint64_t(rect.x) + rect.z <= width && uint64_t(rect.y) + rect.w <= height;
}

} // namespace tessera::backend
