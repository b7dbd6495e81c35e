#pragma once
/// @file SubdivMeshData.h
/// A Catmull-Clark surface packed for the GPU, as createSubdiv takes it
/// (SubdivDesc::mesh): the stencils that refine a frame's base vertices into
/// control points and level-of-detail points, the patches, a quadtree per
/// ptex face to find a point's patch, and the tessellation domains with their
/// owners for watertight edges, as the arrays of SubdivLayout.h. Plain data:
/// a backend uploads it as is. tessera_subdiv packs it from a surface
/// (subdiv::SubdivGpuMesh::build); the contract needs only its layout, so it
/// lives here and the core never depends on the subdivision library.

#include "tessera/scene/Aabb.h"
#include "tessera/shaders/SubdivLayout.h"

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::backend {

struct SubdivMeshData {
    std::string name;
    uint32_t baseVertexCount = 0;
    /// Control points (the surface's controlPoints() order); the corner
    /// (LOD) points follow them in the refined points.
    uint32_t controlPointCount = 0;
    uint32_t cornerPointCount = 0;
    uint32_t ptexFaceCount = 0;
    /// No boundary: back faces may be culled (SubdivDomains::closed).
    bool closed = true;
    /// The shape's base positions (the rest pose).
    std::vector<glm::vec3> restPositions;

    /// Per refined point: (first entry, entry count, w as float bits, 0);
    /// the point is the weighted sum of the entries' base vertices, its w
    /// the record's (1 for control points, the LOD radius for corners).
    std::vector<glm::uvec4> stencils;
    /// (base vertex, weight as float bits).
    std::vector<glm::uvec2> stencilEntries;
    std::vector<shader::SubdivPatch> patches;
    std::vector<uint32_t> patchIndices;
    /// Quadtree nodes: node p < ptexFaceCount is ptex face p's root; each
    /// child is TS_SUBDIV_LEAF | patch, a node, or TS_SUBDIV_EMPTY.
    std::vector<glm::uvec4> nodes;
    std::vector<shader::SubdivDomain> domains;
    std::vector<uint32_t> support;
    /// Bounds of the rest pose's control points.
    scene::Aabb bounds;

    uint32_t refinedPointCount() const { return controlPointCount + cornerPointCount; }
    uint32_t domainCount() const { return uint32_t(domains.size()); }
};

} // namespace tessera::backend
