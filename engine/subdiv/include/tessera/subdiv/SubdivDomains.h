#pragma once
/// @file SubdivDomains.h
/// A control mesh's tessellation domains: the quads the tessellator
/// subdivides, where each domain's corners stand for level of detail, which
/// domain evaluates each shared edge and corner (the watertight rule of
/// SubdivLayout.h), and the 1-ring of base vertices that bounds each
/// domain's limit surface. CPU only, without OpenSubdiv; SubdivGpuMesh
/// packs it for the GPU.
///
/// Domains must meet edge to edge, or a shared edge would be tessellated
/// from each side with points that do not coincide (a T-junction). Ptex
/// faces do not: an n-gon's sub-faces meet a neighbouring quad on half its
/// edge. So a mesh with any non-quad face is tessellated one level down,
/// over the faces of its first Catmull-Clark refinement: each quad's ptex
/// face in four quadrants, each n-gon's sub-face whole. A mesh of quads
/// only takes one domain per face.

#include "tessera/core/Result.h"
#include "tessera/subdiv/ObjShape.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

class SubdivDomains {
public:
    /// A corner's level-of-detail point: the average of base vertices (one
    /// for a base vertex, two for an edge midpoint, all of a face for its
    /// centre).
    struct CornerPoint {
        uint32_t firstVertex = 0; ///< into cornerVertices()
        uint32_t vertexCount = 0;
        /// Half the mean rest length of the domain edges meeting there: the
        /// radius whose projection sets the corner's tessellation level.
        float radius = 0.0f;
        /// An extraordinary vertex of the limit surface: an interior point
        /// where other than four domains meet, or a boundary point with
        /// more than two.
        bool extraordinary = false;
    };

    /// Where a domain lies: a ptex face (OpenSubdiv's order,
    /// Far::PtexIndices), whole or one quadrant of it.
    struct Placement {
        uint32_t ptexFace = 0;
        /// 0..3 (bit 0: upper half in u, bit 1 in v), or kWhole.
        uint32_t quadrant = kWhole;
    };
    static constexpr uint32_t kWhole = 4;

    /// A domain edge or corner as another domain sees it.
    struct EdgeRef {
        uint32_t domain = 0;
        uint32_t edge = 0;    ///< outer-level order
        bool flipped = false; ///< runs the other way there (t -> 1 - t)
    };
    struct CornerRef {
        uint32_t domain = 0;
        uint32_t corner = 0; ///< domain order
    };

    /// Builds the domains of a shape ObjShape accepted (manifold, faces of
    /// 3 .. kMaxFaceVertices vertices). Error, naming the shape: faces or
    /// indices that do not hold together, or a non-manifold edge.
    static Result<SubdivDomains> build(const ObjShape& shape);

    uint32_t domainCount() const { return uint32_t(mPlacement.size()); }
    uint32_t ptexFaceCount() const { return mFirstPtex.back(); }
    /// True when quads are split into quadrants (the mesh has non-quads).
    bool splitQuads() const { return mSplitQuads; }
    /// True when the drawn surface has no boundary (every domain edge is
    /// shared by two drawn domains): a closed surface whose back faces
    /// can be culled.
    bool closed() const { return mClosed; }
    const Placement& placement(uint32_t domain) const { return mPlacement[domain]; }
    uint32_t baseFaceOf(uint32_t domain) const { return mBaseFace[domain]; }
    /// First ptex face of a base face (Far::PtexIndices::GetFaceId).
    uint32_t firstPtexFace(uint32_t baseFace) const { return mFirstPtex[baseFace]; }
    bool isHole(uint32_t domain) const { return mHole[domain] != 0; }
    /// Ptex (u, v) of a domain's (u, v): exact (a halving and an offset).
    glm::vec2 toPtex(uint32_t domain, glm::vec2 uv) const;

    /// Corner points and the base vertices they average.
    std::span<const CornerPoint> cornerPoints() const { return mCornerPoints; }
    std::span<const uint32_t> cornerVertices() const { return mCornerVertices; }
    /// The corner points of a domain, domain order.
    const std::array<uint32_t, 4>& corners(uint32_t domain) const { return mCorners[domain]; }

    /// Who evaluates the points of edge `edge` of `domain`: the
    /// lowest-numbered drawn domain (not a hole) sharing it; itself on a
    /// boundary.
    const EdgeRef& edgeOwner(uint32_t domain, uint32_t edge) const { return mEdgeOwners[domain][edge]; }
    /// Who evaluates corner `corner` of `domain`, by the same rule.
    const CornerRef& cornerOwner(uint32_t domain, uint32_t corner) const { return mCornerOwners[domain][corner]; }
    /// The domain across an edge (holes included), if any.
    std::optional<EdgeRef> neighbour(uint32_t domain, uint32_t edge) const;

    /// The base vertices of a domain's base face and of every face sharing
    /// a vertex with it: the limit surface over the face lies in their
    /// convex hull (Catmull-Clark's rules, creases included, weigh
    /// non-negatively). Domains of one base face share it.
    std::span<const uint32_t> support(uint32_t domain) const;
    uint32_t supportOffset(uint32_t domain) const { return mSupportFirst[mBaseFace[domain]]; }
    uint32_t supportCount(uint32_t domain) const;
    std::span<const uint32_t> supportIndices() const { return mSupport; }

    /// Positions of the corner points for the given base positions.
    std::vector<glm::vec3> cornerPositions(std::span<const glm::vec3> basePositions) const;

private:
    friend class SubdivDomainsBuilder;
    bool mSplitQuads = false;
    bool mClosed = true;
    std::vector<Placement> mPlacement;
    std::vector<uint32_t> mBaseFace;
    std::vector<uint32_t> mFirstPtex; ///< per base face, plus the total
    std::vector<uint8_t> mHole;
    std::vector<CornerPoint> mCornerPoints;
    std::vector<uint32_t> mCornerVertices;
    std::vector<std::array<uint32_t, 4>> mCorners;
    std::vector<std::array<EdgeRef, 4>> mEdgeOwners;
    std::vector<std::array<CornerRef, 4>> mCornerOwners;
    std::vector<std::array<EdgeRef, 4>> mNeighbours; ///< self where none
    std::vector<uint32_t> mSupport;
    std::vector<uint32_t> mSupportFirst; ///< per base face, plus the total
};

} // namespace tessera::subdiv
