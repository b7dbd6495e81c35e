#include "tessera/subdiv/SubdivGpuMesh.h"

#include "tessera/subdiv/SubdivDomains.h"
#include "tessera/subdiv/SubdivSurface.h"

#include <bit>
#include <string>

namespace tessera::subdiv {

namespace {

uint32_t floatBits(float value) {
    return std::bit_cast<uint32_t>(value);
}

/// Inserts `patch` into its ptex face's quadtree at the square its
/// parameters give (depth levels below the ptex face).
Status insertPatch(SubdivGpuMesh& mesh, uint32_t patchIndex, const PatchParam& param) {
    const uint32_t depth = param.depth() - (param.nonQuadRoot() ? 1u : 0u);
    if (depth > TS_SUBDIV_MAX_DEPTH)
        return fail(mesh.name, ": a patch at depth ", std::to_string(depth), " is deeper than the GPU's quadtree (",
                    std::to_string(TS_SUBDIV_MAX_DEPTH), ")");
    const uint32_t leaf = TS_SUBDIV_LEAF | patchIndex;
    uint32_t node = param.ptexFace();
    if (depth == 0) {
        mesh.nodes[node] = glm::uvec4(leaf);
        return {};
    }
    for (uint32_t level = 1; level <= depth; ++level) {
        const uint32_t shift = depth - level;
        const uint32_t quadrant = ((param.u() >> shift) & 1u) | (((param.v() >> shift) & 1u) << 1u);
        if (level == depth) {
            mesh.nodes[node][quadrant] = leaf;
            break;
        }
        uint32_t child = mesh.nodes[node][quadrant];
        if (child == TS_SUBDIV_EMPTY) {
            child = uint32_t(mesh.nodes.size());
            mesh.nodes[node][quadrant] = child;
            mesh.nodes.push_back(glm::uvec4(TS_SUBDIV_EMPTY));
        } else if (child & TS_SUBDIV_LEAF) {
            return fail(mesh.name, ": patches of ptex face ", std::to_string(param.ptexFace()), " overlap");
        }
        node = child;
    }
    return {};
}

/// Bits of the patch's corners (domain order) that are extraordinary: only
/// ptex face corners can be (after one refinement the extraordinary points
/// are base vertices and n-gon centres).
uint32_t extraordinaryCorners(const PatchParam& param, const glm::bvec4& ptexCorners) {
    const uint32_t depth = param.depth() - (param.nonQuadRoot() ? 1u : 0u);
    const uint32_t last = (1u << depth) - 1u;
    const uint32_t u = param.u(), v = param.v();
    const bool at[4] = {u == 0 && v == 0, u == last && v == 0, u == last && v == last, u == 0 && v == last};
    uint32_t bits = 0;
    for (uint32_t c = 0; c < 4; ++c)
        if (at[c] && ptexCorners[c]) bits |= 1u << c;
    return bits;
}

} // namespace

Result<SubdivGpuMesh> SubdivGpuMesh::build(const ObjShape& shape, const SubdivSurface& surface) {
    Result<SubdivDomains> built = SubdivDomains::build(shape);
    if (!built) return built.error();
    const SubdivDomains& domains = built.value();
    SubdivGpuMesh mesh;
    mesh.name = shape.name;
    if (surface.baseVertexCount() != shape.positions.size() || surface.ptexFaceCount() != domains.ptexFaceCount())
        return fail(shape.name, ": the surface was not made from this shape");
    mesh.baseVertexCount = surface.baseVertexCount();
    mesh.controlPointCount = uint32_t(surface.controlPoints().size());
    mesh.cornerPointCount = uint32_t(domains.cornerPoints().size());
    mesh.ptexFaceCount = domains.ptexFaceCount();
    mesh.bounds = surface.bounds();
    mesh.restPositions = shape.positions;
    mesh.closed = domains.closed();

    const RefineStencils refine = surface.refineStencils();
    for (uint32_t i = 0; i < refine.pointCount(); ++i)
        mesh.stencils.push_back({refine.offsets[i], refine.sizes[i], floatBits(1.0f), 0u});
    for (uint32_t k = 0; k < refine.entryCount(); ++k)
        mesh.stencilEntries.push_back({refine.indices[k], floatBits(refine.weights[k])});
    for (const SubdivDomains::CornerPoint& c : domains.cornerPoints()) {
        mesh.stencils.push_back({uint32_t(mesh.stencilEntries.size()), c.vertexCount, floatBits(c.radius), 0u});
        const float weight = 1.0f / float(c.vertexCount);
        for (uint32_t k = 0; k < c.vertexCount; ++k)
            mesh.stencilEntries.push_back({domains.cornerVertices()[c.firstVertex + k], floatBits(weight)});
    }

    // Extraordinary ptex-face corners, read off the domains at them.
    std::vector<glm::bvec4> ptexCorners(mesh.ptexFaceCount, glm::bvec4(false));
    for (uint32_t d = 0; d < domains.domainCount(); ++d) {
        const SubdivDomains::Placement& place = domains.placement(d);
        for (uint32_t c = 0; c < 4; ++c) {
            // A quadrant holds ptex corner c only as its own corner c, in
            // quadrant c's position order (0, 1, 3, 2).
            const bool holds = place.quadrant == SubdivDomains::kWhole || place.quadrant == (c < 2 ? c : 5 - c);
            if (holds && domains.cornerPoints()[domains.corners(d)[c]].extraordinary) ptexCorners[place.ptexFace][c] = true;
        }
    }

    mesh.nodes.assign(mesh.ptexFaceCount, glm::uvec4(TS_SUBDIV_EMPTY));
    const std::span<const Patch> patches = surface.patches();
    for (uint32_t p = 0; p < patches.size(); ++p) {
        const Patch& patch = patches[p];
        const uint32_t info = uint32_t(patch.type) |
                              (extraordinaryCorners(patch.param, ptexCorners[patch.param.ptexFace()])
                               << TS_SUBDIV_PATCH_EV_SHIFT);
        mesh.patches.push_back({glm::uvec4(info, patch.firstIndex, patch.param.field0, patch.param.field1)});
        if (Status inserted = insertPatch(mesh, p, patch.param); !inserted) return inserted.error();
    }
    const std::span<const uint32_t> indices = surface.patchPointIndices();
    mesh.patchIndices.assign(indices.begin(), indices.end());

    const uint32_t controlPoints = mesh.controlPointCount;
    for (uint32_t d = 0; d < domains.domainCount(); ++d) {
        shader::SubdivDomain record{};
        const SubdivDomains::Placement& place = domains.placement(d);
        record.topology = glm::uvec4(place.ptexFace, domains.supportOffset(d), domains.supportCount(d),
                                     (domains.isHole(d) ? TS_SUBDIV_DOMAIN_HOLE : 0u) | (place.quadrant << 8u));
        for (uint32_t k = 0; k < 4; ++k) {
            record.corners[k] = controlPoints + domains.corners(d)[k];
            const SubdivDomains::EdgeRef& edge = domains.edgeOwner(d, k);
            record.edges[k] = (edge.domain << 3u) | (edge.edge << 1u) | (edge.flipped ? 1u : 0u);
            const SubdivDomains::CornerRef& corner = domains.cornerOwner(d, k);
            record.cornerOwners[k] = (corner.domain << 2u) | corner.corner;
        }
        mesh.domains.push_back(record);
    }
    const std::span<const uint32_t> support = domains.supportIndices();
    mesh.support.assign(support.begin(), support.end());
    return mesh;
}

uint32_t SubdivGpuMesh::findPatch(uint32_t ptexFace, glm::vec2 uv) const {
    uint32_t node = ptexFace;
    for (uint32_t level = 0; level <= TS_SUBDIV_MAX_DEPTH; ++level) {
        const uint32_t quadrant = shader::tsSubdivQuadrant(uv);
        const uint32_t child = nodes[node][quadrant];
        if (child == TS_SUBDIV_EMPTY || (child & TS_SUBDIV_LEAF)) return child == TS_SUBDIV_EMPTY ? child : child & ~TS_SUBDIV_LEAF;
        uv = shader::tsSubdivIntoQuadrant(uv, quadrant);
        node = child;
    }
    return TS_SUBDIV_EMPTY;
}

std::vector<glm::vec4> SubdivGpuMesh::refine(std::span<const glm::vec3> basePositions) const {
    std::vector<glm::vec4> points;
    points.reserve(stencils.size());
    for (const glm::uvec4& s : stencils) {
        glm::vec3 sum(0.0f);
        for (uint32_t k = 0; k < s.y; ++k) {
            const glm::uvec2 entry = stencilEntries[s.x + k];
            sum += std::bit_cast<float>(entry.y) * basePositions[entry.x];
        }
        points.emplace_back(sum, std::bit_cast<float>(s.z));
    }
    return points;
}

} // namespace tessera::subdiv
