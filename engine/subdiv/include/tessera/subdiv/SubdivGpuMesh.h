#pragma once
/// @file SubdivGpuMesh.h
/// Everything a GPU needs to draw a SubdivSurface: the contract's packed
/// arrays (backend::SubdivMeshData, SubdivLayout.h's layouts) built from a
/// surface, with the CPU twins of the shaders' quadtree walk and refinement.
/// Nothing here depends on OpenSubdiv or the device.

#include "tessera/backend/SubdivMeshData.h"
#include "tessera/core/Result.h"
#include "tessera/subdiv/ObjShape.h"

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

class SubdivSurface;

/// The packed surface; passes to createSubdiv as it is (SubdivDesc::mesh).
struct SubdivGpuMesh : backend::SubdivMeshData {
    /// Packs `surface`, made from `shape` (the same shape, or an error
    /// naming it). Also fails when the quadtree would need more depth than
    /// TS_SUBDIV_MAX_DEPTH.
    static Result<SubdivGpuMesh> build(const ObjShape& shape, const SubdivSurface& surface);

    /// The patch holding ptex (u, v) of `ptexFace` by walking the quadtree
    /// as the shaders do (TS_SUBDIV_EMPTY when none).
    uint32_t findPatch(uint32_t ptexFace, glm::vec2 uv) const;
    /// Applies the stencils to base positions (the CPU twin of every
    /// backend's refine pass), xyz and w as the GPU writes them.
    std::vector<glm::vec4> refine(std::span<const glm::vec3> basePositions) const;
};

} // namespace tessera::subdiv
