#include "tessera/subdiv/SubdivDomains.h"

#include <algorithm>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>

namespace tessera::subdiv {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

/// Domain edges (outer-level order) as corner pairs (start, end).
constexpr uint32_t kEdgeCorners[4][2] = {{0, 3}, {0, 1}, {1, 2}, {3, 2}};

/// A corner point's identity: a base vertex, the midpoint of a base edge
/// (smaller vertex first) or the centre of a base face.
struct CornerKey {
    enum Kind : uint32_t { Vertex, EdgeMidpoint, FaceCentre } kind = Vertex;
    uint32_t a = 0, b = 0;
    bool operator<(const CornerKey& o) const { return std::tie(kind, a, b) < std::tie(o.kind, o.a, o.b); }
};

uint64_t edgeKey(uint32_t a, uint32_t b) {
    return (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

} // namespace

/// The steps of SubdivDomains::build, one member each.
class SubdivDomainsBuilder {
public:
    SubdivDomainsBuilder(const ObjShape& shape, SubdivDomains& d) : mShape(shape), mD(d) {}

    Status run() {
        uint64_t total = 0;
        for (uint32_t size : mShape.faceSizes) {
            if (size < 3 || size > kMaxFaceVertices)
                return fail(mShape.name, ": a face of ", std::to_string(size), " vertices cannot be tessellated");
            mFaceStart.push_back(uint32_t(total));
            total += size;
            mD.mSplitQuads = mD.mSplitQuads || size != 4;
        }
        if (total != mShape.faceVertices.size())
            return fail(mShape.name, ": face sizes add up to ", std::to_string(total), " corners, but ",
                        std::to_string(mShape.faceVertices.size()), " are given");
        for (uint32_t v : mShape.faceVertices)
            if (v >= mShape.positions.size())
                return fail(mShape.name, ": a face names vertex ", std::to_string(v), " of ",
                            std::to_string(mShape.positions.size()));
        makeDomains();
        if (Status edges = makeEdges(); !edges) return edges;
        makeCorners();
        makePointProperties();
        makeSupports();
        return {};
    }

private:
    const uint32_t* faceVertices(uint32_t f) const { return mShape.faceVertices.data() + mFaceStart[f]; }

    uint32_t point(CornerKey key, std::span<const uint32_t> vertices) {
        auto [it, inserted] = mPointIds.emplace(key, uint32_t(mD.mCornerPoints.size()));
        if (inserted) {
            mD.mCornerPoints.push_back({uint32_t(mD.mCornerVertices.size()), uint32_t(vertices.size())});
            mD.mCornerVertices.insert(mD.mCornerVertices.end(), vertices.begin(), vertices.end());
        }
        return it->second;
    }
    uint32_t vertexPoint(const uint32_t* fv, uint32_t k) { return point({CornerKey::Vertex, fv[k], 0}, {fv + k, 1}); }
    uint32_t midpoint(const uint32_t* fv, uint32_t k0, uint32_t k1) {
        const uint32_t pair[2] = {fv[k0], fv[k1]};
        return point({CornerKey::EdgeMidpoint, std::min(pair[0], pair[1]), std::max(pair[0], pair[1])}, pair);
    }

    void addDomain(uint32_t face, uint32_t ptex, uint32_t quadrant, const std::array<uint32_t, 4>& corners) {
        mD.mPlacement.push_back({ptex, quadrant});
        mD.mBaseFace.push_back(face);
        mD.mCorners.push_back(corners);
    }

    void makeDomains() {
        std::vector<uint8_t> hole(mShape.faceCount(), 0);
        for (uint32_t h : mShape.holes)
            if (h < mShape.faceCount()) hole[h] = 1;
        uint32_t ptex = 0;
        for (uint32_t f = 0; f < mShape.faceCount(); ++f) {
            const uint32_t n = mShape.faceSizes[f];
            const uint32_t* fv = faceVertices(f);
            mD.mFirstPtex.push_back(ptex);
            if (n == 4 && !mD.mSplitQuads) {
                addDomain(f, ptex, SubdivDomains::kWhole,
                          {vertexPoint(fv, 0), vertexPoint(fv, 1), vertexPoint(fv, 2), vertexPoint(fv, 3)});
            } else if (n == 4) {
                // The ptex face's 3x3 lattice of half-unit points: the
                // vertices (0,0) v0, (2,0) v1, (2,2) v2, (0,2) v3, the edge
                // midpoints between them and the centre.
                const uint32_t centre = point({CornerKey::FaceCentre, f, 0}, {fv, 4});
                const uint32_t lattice[3][3] = {
                    {vertexPoint(fv, 0), midpoint(fv, 0, 1), vertexPoint(fv, 1)},
                    {midpoint(fv, 3, 0), centre, midpoint(fv, 1, 2)},
                    {vertexPoint(fv, 3), midpoint(fv, 2, 3), vertexPoint(fv, 2)}};
                for (uint32_t q = 0; q < 4; ++q) {
                    const uint32_t i = q & 1u, j = q >> 1u;
                    addDomain(f, ptex, q, {lattice[j][i], lattice[j][i + 1], lattice[j + 1][i + 1], lattice[j + 1][i]});
                }
            } else {
                // FaceParameterization: sub-face k has (0,0) at vertex k, u
                // towards the midpoint of edge (k, k+1), v towards that of
                // (k-1, k), (1,1) at the centre.
                const uint32_t centre = point({CornerKey::FaceCentre, f, 0}, {fv, n});
                for (uint32_t k = 0; k < n; ++k)
                    addDomain(f, ptex + k, SubdivDomains::kWhole,
                              {vertexPoint(fv, k), midpoint(fv, k, (k + 1) % n), centre, midpoint(fv, (k + n - 1) % n, k)});
            }
            ptex += n == 4 ? 1 : n;
            for (size_t d = mD.mHole.size(); d < mD.mPlacement.size(); ++d) mD.mHole.push_back(hole[f]);
        }
        mD.mFirstPtex.push_back(ptex);
    }

    Status makeEdges() {
        const uint32_t domains = mD.domainCount();
        for (uint32_t d = 0; d < domains; ++d)
            for (uint32_t e = 0; e < 4; ++e) mEdges[key(d, e)].push_back({d, e});
        mD.mEdgeOwners.resize(domains);
        mD.mNeighbours.resize(domains);
        for (uint32_t d = 0; d < domains; ++d) {
            for (uint32_t e = 0; e < 4; ++e) {
                const auto& sharing = mEdges[key(d, e)];
                if (sharing.size() > 2)
                    return fail(mShape.name, ": an edge of base face ", std::to_string(mD.mBaseFace[d]),
                                " is shared by more than two faces (non-manifold)");
                const uint32_t start = mD.mCorners[d][kEdgeCorners[e][0]];
                SubdivDomains::EdgeRef owner{d, e, false};
                mD.mNeighbours[d][e] = owner;
                for (const auto& [other, otherEdge] : sharing) {
                    if (other == d) continue;
                    const SubdivDomains::EdgeRef ref{other, otherEdge,
                                                     mD.mCorners[other][kEdgeCorners[otherEdge][0]] != start};
                    mD.mNeighbours[d][e] = ref;
                    if (!mD.mHole[other] && (mD.mHole[d] || other < d)) owner = ref;
                }
                mD.mEdgeOwners[d][e] = owner;
            }
        }
        return {};
    }

    uint64_t key(uint32_t d, uint32_t e) const {
        return edgeKey(mD.mCorners[d][kEdgeCorners[e][0]], mD.mCorners[d][kEdgeCorners[e][1]]);
    }

    void makeCorners() {
        mPointOwner.assign(mD.mCornerPoints.size(), {kNone, 0});
        mPointDomains.assign(mD.mCornerPoints.size(), 0);
        for (uint32_t d = 0; d < mD.domainCount(); ++d) {
            if (mD.mHole[d]) continue;
            for (uint32_t c = 0; c < 4; ++c) {
                const uint32_t id = mD.mCorners[d][c];
                ++mPointDomains[id];
                if (mPointOwner[id].domain == kNone) mPointOwner[id] = {d, c};
            }
        }
        mD.mCornerOwners.resize(mD.domainCount());
        for (uint32_t d = 0; d < mD.domainCount(); ++d)
            for (uint32_t c = 0; c < 4; ++c) {
                const SubdivDomains::CornerRef& owner = mPointOwner[mD.mCorners[d][c]];
                mD.mCornerOwners[d][c] = owner.domain == kNone ? SubdivDomains::CornerRef{d, c} : owner;
            }
    }

    /// Radii from the drawn domains' rest edge lengths; extraordinary points
    /// from how many drawn domains meet there, on a boundary or not.
    void makePointProperties() {
        const size_t points = mD.mCornerPoints.size();
        std::vector<double> lengthSum(points, 0.0);
        std::vector<uint32_t> edgeCount(points, 0), boundaryEdges(points, 0);
        const std::vector<glm::vec3> rest = mD.cornerPositions(mShape.positions);
        for (const auto& [edge, sharing] : mEdges) {
            uint32_t drawn = 0;
            for (const auto& s : sharing) drawn += mD.mHole[s.first] ? 0u : 1u;
            if (drawn == 0) continue;
            if (drawn == 1) mD.mClosed = false;
            const auto& [d, e] = sharing.front();
            const uint32_t a = mD.mCorners[d][kEdgeCorners[e][0]], b = mD.mCorners[d][kEdgeCorners[e][1]];
            const double length = glm::distance(glm::dvec3(rest[a]), glm::dvec3(rest[b]));
            for (uint32_t id : {a, b}) {
                lengthSum[id] += length;
                ++edgeCount[id];
                boundaryEdges[id] += drawn == 1 ? 1u : 0u;
            }
        }
        for (size_t id = 0; id < points; ++id) {
            SubdivDomains::CornerPoint& c = mD.mCornerPoints[id];
            c.radius = edgeCount[id] ? float(0.5 * lengthSum[id] / edgeCount[id]) : 0.0f;
            const uint32_t meeting = mPointDomains[id];
            c.extraordinary = boundaryEdges[id] > 0 ? meeting > 2 : (meeting > 0 && meeting != 4);
        }
    }

    void makeSupports() {
        std::vector<std::vector<uint32_t>> vertexFaces(mShape.positions.size());
        for (uint32_t f = 0; f < mShape.faceCount(); ++f)
            for (uint32_t k = 0; k < mShape.faceSizes[f]; ++k) vertexFaces[faceVertices(f)[k]].push_back(f);
        for (uint32_t f = 0; f < mShape.faceCount(); ++f) {
            std::vector<uint32_t> ring;
            for (uint32_t k = 0; k < mShape.faceSizes[f]; ++k)
                for (uint32_t g : vertexFaces[faceVertices(f)[k]])
                    ring.insert(ring.end(), faceVertices(g), faceVertices(g) + mShape.faceSizes[g]);
            std::sort(ring.begin(), ring.end());
            ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
            mD.mSupportFirst.push_back(uint32_t(mD.mSupport.size()));
            mD.mSupport.insert(mD.mSupport.end(), ring.begin(), ring.end());
        }
        mD.mSupportFirst.push_back(uint32_t(mD.mSupport.size()));
    }

    const ObjShape& mShape;
    SubdivDomains& mD;
    std::vector<uint32_t> mFaceStart;
    std::map<CornerKey, uint32_t> mPointIds;
    std::unordered_map<uint64_t, std::vector<std::pair<uint32_t, uint32_t>>> mEdges;
    std::vector<SubdivDomains::CornerRef> mPointOwner;
    std::vector<uint32_t> mPointDomains;
};

Result<SubdivDomains> SubdivDomains::build(const ObjShape& shape) {
    SubdivDomains domains;
    if (Status built = SubdivDomainsBuilder(shape, domains).run(); !built) return built.error();
    return domains;
}

glm::vec2 SubdivDomains::toPtex(uint32_t domain, glm::vec2 uv) const {
    const uint32_t q = mPlacement[domain].quadrant;
    if (q == kWhole) return uv;
    return (uv + glm::vec2(float(q & 1u), float(q >> 1u))) * 0.5f;
}

std::optional<SubdivDomains::EdgeRef> SubdivDomains::neighbour(uint32_t domain, uint32_t edge) const {
    const EdgeRef& n = mNeighbours[domain][edge];
    if (n.domain == domain) return std::nullopt;
    return n;
}

std::span<const uint32_t> SubdivDomains::support(uint32_t domain) const {
    return std::span<const uint32_t>(mSupport).subspan(supportOffset(domain), supportCount(domain));
}

uint32_t SubdivDomains::supportCount(uint32_t domain) const {
    const uint32_t base = mBaseFace[domain];
    return mSupportFirst[base + 1] - mSupportFirst[base];
}

std::vector<glm::vec3> SubdivDomains::cornerPositions(std::span<const glm::vec3> basePositions) const {
    std::vector<glm::vec3> positions;
    positions.reserve(mCornerPoints.size());
    for (const CornerPoint& c : mCornerPoints) {
        glm::dvec3 sum(0.0);
        for (uint32_t k = 0; k < c.vertexCount; ++k) sum += glm::dvec3(basePositions[mCornerVertices[c.firstVertex + k]]);
        positions.push_back(glm::vec3(sum / double(c.vertexCount)));
    }
    return positions;
}

} // namespace tessera::subdiv
