#pragma once
/// @file SubdivGpuMesh.h
/// Everything a GPU needs to draw a SubdivSurface, as the arrays of
/// SubdivLayout.h: the stencils that refine this frame's base vertices into
/// control points and level-of-detail points, the patches, a quadtree per
/// ptex face to find a point's patch, and the tessellation domains with
/// their owners for watertight edges (SubdivDomains). Plain data: a backend
/// uploads it as is, and nothing here depends on OpenSubdiv or the device.

#include "tessera/shaders/SubdivLayout.h"
#include "tessera/core/Result.h"
#include "tessera/scene/Aabb.h"
#include "tessera/subdiv/ObjShape.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

class SubdivSurface;

struct SubdivGpuMesh {
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
