// Watertightness on the CPU: every point of a patch edge is evaluated from
// every patch that touches it (across base faces, between the sub-faces of
// a non-quad, across transition edges between depths, between end caps and
// regular patches) and the positions compared. A crack-free GPU
// tessellation relies on this; the figures say what holds bit-exactly.
//
// Points are matched topologically, not geometrically: a patch-edge point
// is named by the base vertex, base edge (and the fraction along it), the
// non-quad's interior sub-face edge, the face centre or the ptex-face point
// it lies on. Samples are dyadic fractions on one absolute spacing, exact in
// double, so a coarse patch's edge samples coincide exactly with a finer
// neighbour's, and a point inside the mesh that only one patch reaches is a
// hole in the patches.
#include "SubdivTestSupport.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>

namespace tessera::subdiv::test {
namespace {

// Where a point on a ptex face's boundary or interior lies, in terms of the
// base mesh (kinds in order: base vertex, base edge, non-quad interior
// sub-face edge, non-quad centre, inside one ptex face).
struct PointKey {
    enum Kind { Vertex, Edge, SubFaceEdge, Centre, Inside } kind;
    uint32_t a = 0, b = 0;
    double x = 0.0, y = 0.0;
    auto tie() const { return std::tie(kind, a, b, x, y); }
    bool operator<(const PointKey& o) const { return tie() < o.tie(); }
};

struct FaceTopology {
    std::vector<uint32_t> first; // per face, its first face-vertex
    const ObjShape& shape;
    explicit FaceTopology(const ObjShape& s) : shape(s) {
        uint32_t corner = 0;
        for (uint32_t size : s.faceSizes) first.push_back(corner), corner += size;
    }
    uint32_t vertex(uint32_t face, uint32_t k) const {
        uint32_t n = shape.faceSizes[face];
        return shape.faceVertices[first[face] + (k % n)];
    }
};

PointKey edgeKey(uint32_t from, uint32_t to, double fraction) {
    if (fraction == 0.0) return {PointKey::Vertex, from};
    if (fraction == 1.0) return {PointKey::Vertex, to};
    if (from > to) std::swap(from, to), fraction = 1.0 - fraction; // exact for dyadic fractions
    return {PointKey::Edge, from, to, fraction};
}

PointKey keyOf(const FaceTopology& topo, const PtexOwner& owner, uint32_t ptex, glm::dvec2 uv) {
    const uint32_t f = owner.face, n = topo.shape.faceSizes[f];
    const double u = uv.x, v = uv.y;
    if (u > 0.0 && u < 1.0 && v > 0.0 && v < 1.0) return {PointKey::Inside, ptex, 0, u, v};
    if (n == 4) {
        // Edge e of the quad runs from face vertex e to e + 1.
        if (v == 0.0) return edgeKey(topo.vertex(f, 0), topo.vertex(f, 1), u);
        if (u == 1.0) return edgeKey(topo.vertex(f, 1), topo.vertex(f, 2), v);
        if (v == 1.0) return edgeKey(topo.vertex(f, 2), topo.vertex(f, 3), 1.0 - u);
        return edgeKey(topo.vertex(f, 3), topo.vertex(f, 0), 1.0 - v);
    }
    // Sub-face k: (0,0) at vertex k, (1,0) mid-edge (k, k+1), (1,1) the
    // centre, (0,1) mid-edge (k-1, k).
    const uint32_t k = owner.subFace;
    if (u == 1.0 && v == 1.0) return {PointKey::Centre, f};
    if (v == 0.0) return edgeKey(topo.vertex(f, k), topo.vertex(f, k + 1), u / 2.0);
    if (u == 0.0) return edgeKey(topo.vertex(f, k), topo.vertex(f, k + n - 1), v / 2.0);
    if (u == 1.0) return {PointKey::SubFaceEdge, f, k, v}; // to sub-face k+1
    return {PointKey::SubFaceEdge, f, (k + n - 1) % n, u}; // v == 1: to sub-face k-1
}

enum class Pair { SameDepthRegular, TransitionRegular, RegularEndCap, EndCapEndCap, Count };
const char* pairName(Pair p) {
    static const char* names[] = {"regular/regular same depth", "regular/regular across depths", "regular/end cap",
                                  "end cap/end cap"};
    return names[int(p)];
}

struct PairFigures {
    size_t comparisons = 0, bitExact = 0;
    double worst = 0.0; ///< / diagonal
};

struct Sample {
    uint32_t patch;
    glm::dvec3 position;
};

// Base edges (as ordered vertex pairs) with the number of non-hole faces on
// them, and the vertices on an edge with fewer than two.
struct OpenEdges {
    std::map<std::pair<uint32_t, uint32_t>, int> faces;
    std::vector<bool> boundaryVertex;
    explicit OpenEdges(const FaceTopology& topo) : boundaryVertex(topo.shape.positions.size(), false) {
        const ObjShape& shape = topo.shape;
        for (uint32_t f = 0; f < shape.faceCount(); ++f) {
            if (std::find(shape.holes.begin(), shape.holes.end(), f) != shape.holes.end()) continue;
            for (uint32_t k = 0; k < shape.faceSizes[f]; ++k) {
                uint32_t a = topo.vertex(f, k), b = topo.vertex(f, k + 1);
                ++faces[{std::min(a, b), std::max(a, b)}];
            }
        }
        for (const auto& [edge, count] : faces)
            if (count < 2) boundaryVertex[edge.first] = boundaryVertex[edge.second] = true;
    }
    // A point only one patch reaches must be on the open boundary.
    bool onBoundary(const PointKey& key) const {
        if (key.kind == PointKey::Vertex) return boundaryVertex[key.a];
        if (key.kind == PointKey::Edge) return faces.at({key.a, key.b}) < 2;
        return false;
    }
};

std::array<PairFigures, size_t(Pair::Count)> measure(const ObjShape& shape, const SubdivSurface& surface) {
    const FaceTopology topo(shape);
    const std::vector<PtexOwner> owners = ptexOwners(surface);
    std::map<PointKey, std::vector<Sample>> points;
    for (uint32_t p = 0; p < surface.patches().size(); ++p) {
        const PatchParam& param = surface.patches()[p].param;
        // One absolute spacing for every patch (a base edge cut in
        // 2^(maxDepth + 4) steps), so both sides of an edge between depths,
        // or between a quad and a non-quad's half-edge, sample the same
        // points.
        const int steps = 1 << (surface.maxDepth() + 4 - param.depth());
        for (int side = 0; side < 4; ++side)
            for (int i = 0; i <= steps; ++i) {
                const double t = i / double(steps);
                const glm::dvec2 st = side == 0   ? glm::dvec2(t, 0)
                                      : side == 1 ? glm::dvec2(1, t)
                                      : side == 2 ? glm::dvec2(t, 1)
                                                  : glm::dvec2(0, t);
                const PointKey key = keyOf(topo, owners[param.ptexFace()], param.ptexFace(), ptexCoord(param, st));
                points[key].push_back({p, surface.evaluatePatch(p, st).position});
            }
    }
    std::array<PairFigures, size_t(Pair::Count)> figures{};
    const double diagonal = surface.boundsDiagonal();
    const OpenEdges open(topo);
    size_t unmatched = 0;
    for (const auto& [key, samples] : points) {
        // A patch-edge point no other patch reaches is a gap in the
        // patches unless it lies on the mesh's own boundary.
        const bool alone =
            std::all_of(samples.begin(), samples.end(), [&](const Sample& s) { return s.patch == samples[0].patch; });
        if (alone && !open.onBoundary(key)) ++unmatched;
        for (size_t i = 0; i < samples.size(); ++i)
            for (size_t j = i + 1; j < samples.size(); ++j) {
                const Patch& a = surface.patches()[samples[i].patch];
                const Patch& b = surface.patches()[samples[j].patch];
                if (samples[i].patch == samples[j].patch) continue; // a patch corner met twice
                const bool endA = a.type != PatchType::Regular || !a.param.isRegular();
                const bool endB = b.type != PatchType::Regular || !b.param.isRegular();
                const Pair pair = endA && endB                         ? Pair::EndCapEndCap
                                  : endA || endB                       ? Pair::RegularEndCap
                                  : a.param.depth() == b.param.depth() ? Pair::SameDepthRegular
                                                                       : Pair::TransitionRegular;
                PairFigures& f = figures[size_t(pair)];
                ++f.comparisons;
                const glm::dvec3 d = samples[i].position - samples[j].position;
                if (d == glm::dvec3(0.0)) ++f.bitExact;
                f.worst = std::max(f.worst, glm::length(d) / diagonal);
            }
    }
    EXPECT_EQ(unmatched, 0u) << surface.name() << ": patch-edge points inside the mesh that only one patch reaches";
    return figures;
}

void expectWatertight(const ObjShape& shape, const SubdivSettings& settings = {}) {
    const SubdivSurface surface = build(shape, settings);
    const auto figures = measure(shape, surface);
    for (size_t p = 0; p < figures.size(); ++p) {
        const PairFigures& f = figures[p];
        if (f.comparisons == 0) continue;
        std::printf("watertight %-28s %-30s %7zu shared points, %7zu bit-exact, worst %.2e diag\n",
                    surface.name().c_str(), pairName(Pair(p)), f.comparisons, f.bitExact, f.worst);
        EXPECT_LE(f.worst, 1e-6) << surface.name() << ": " << pairName(Pair(p));
    }
}

TEST(Watertight, SharedPatchEdgesAgreeOnEveryShape) {
    for (const ObjShape& shape : allShapes()) expectWatertight(shape);
}

TEST(Watertight, SharedPatchEdgesAgreeWithBSplineEndCaps) {
    SubdivSettings settings;
    settings.endCap = EndCap::BSplineBasis;
    for (const ObjShape& shape : {cube(), pentagonPyramid(false), extraordinaryDisk(), creasedCube(2.0f)})
        expectWatertight(shape, settings);
}

} // namespace
} // namespace tessera::subdiv::test
