// Tessellation domains and their packing for the GPU (SubdivDomains,
// SubdivGpuMesh): domains meet edge to edge, every shared edge and corner
// has one owner that both sides reach bit for bit through the shaders' own
// rule (tsSubdivCanonical, compiled here as C++), the owner's point is the
// same limit point geometrically, the quadtree finds Far's patch, and the
// stencils reproduce OpenSubdiv's control points.
#include "SubdivTestSupport.h"

#include "tessera/subdiv/SubdivDomains.h"
#include "tessera/subdiv/SubdivGpuMesh.h"

#include <bit>
#include <cstdio>

namespace tessera::subdiv::test {
namespace {

struct Built {
    ObjShape shape;
    SubdivSurface surface;
    SubdivDomains domains;
    SubdivGpuMesh mesh;
};

Built buildAll(const ObjShape& shape) {
    SubdivSurface surface = build(shape);
    Result<SubdivDomains> domains = SubdivDomains::build(shape);
    if (!domains) throw std::runtime_error(domains.error().message);
    Result<SubdivGpuMesh> mesh = SubdivGpuMesh::build(shape, surface);
    if (!mesh) throw std::runtime_error(mesh.error().message);
    return {shape, std::move(surface), std::move(domains).value(), std::move(mesh).value()};
}

/// Coordinates along an edge as a D3D11-rule tessellator makes them: 16.16
/// fixed point, so t and 1 - t are both exact floats.
std::vector<float> edgeSamples() {
    std::vector<float> t = {0.0f, 1.0f, 0.5f};
    for (uint32_t k = 1; k < 64; ++k) t.push_back(float(k * 977u % 65536u) / 65536.0f);
    return t;
}

/// Where a domain point is evaluated: (domain, u, v) as tsSubdivCanonical gives it.
struct Evaluated {
    uint32_t domain;
    glm::vec2 uv;
    bool operator==(const Evaluated& o) const {
        return domain == o.domain && std::bit_cast<glm::uvec2>(uv) == std::bit_cast<glm::uvec2>(o.uv);
    }
};

Evaluated canonical(const SubdivGpuMesh& mesh, uint32_t domain, glm::vec2 uv) {
    Evaluated result{};
    shader::tsSubdivCanonical(mesh.domains[domain], domain, uv, result.domain, result.uv);
    return result;
}

glm::dvec3 limitAt(const Built& b, const Evaluated& at) {
    const uint32_t ptex = b.domains.placement(at.domain).ptexFace;
    std::optional<LimitPoint> p = b.surface.evaluatePtex(ptex, glm::dvec2(b.domains.toPtex(at.domain, at.uv)));
    return p ? p->position : glm::dvec3(std::nan(""));
}

TEST(SubdivDomains, SharedEdgesAndCornersHaveOneOwnerBothSidesReach) {
    const std::vector<float> samples = edgeSamples();
    for (const ObjShape& shape : allShapes()) {
        SCOPED_TRACE(shape.name);
        const Built b = buildAll(shape);
        const double tolerance = 1e-6 * b.surface.boundsDiagonal();
        uint32_t sharedEdges = 0, checked = 0;
        double worst = 0.0;
        for (uint32_t d = 0; d < b.domains.domainCount(); ++d) {
            if (b.domains.isHole(d)) continue;
            for (uint32_t e = 0; e < 4; ++e) {
                std::optional<SubdivDomains::EdgeRef> across = b.domains.neighbour(d, e);
                if (!across || b.domains.isHole(across->domain)) continue;
                ++sharedEdges;
                // The neighbour sees this edge as its edge `across->edge`.
                ASSERT_EQ(b.domains.neighbour(across->domain, across->edge)->domain, d);
                for (float t : samples) {
                    const float there = across->flipped ? 1.0f - t : t;
                    const Evaluated mine = canonical(b.mesh, d, shader::tsSubdivEdgePoint(e, t));
                    const Evaluated theirs =
                        canonical(b.mesh, across->domain, shader::tsSubdivEdgePoint(across->edge, there));
                    ASSERT_TRUE(mine == theirs) << "domain " << d << " edge " << e << " t " << t;
                    // The neighbour's own point, evaluated there without the
                    // rule, is the same limit point up to rounding.
                    const Evaluated direct{across->domain, shader::tsSubdivEdgePoint(across->edge, there)};
                    worst = std::max(worst, glm::distance(limitAt(b, mine), limitAt(b, direct)));
                    ++checked;
                }
            }
        }
        EXPECT_LE(worst, tolerance);
        std::printf("[domains] %s: %u domains (%s), %u corner points, %u shared edge sides, %u points, worst %.2g of "
                    "the diagonal\n",
                    shape.name.c_str(), b.domains.domainCount(), b.domains.splitQuads() ? "quads split" : "whole",
                    uint32_t(b.domains.cornerPoints().size()), sharedEdges, checked,
                    worst / b.surface.boundsDiagonal());
    }
}

TEST(SubdivDomains, CornersOfEveryDomainMeetingThereEvaluateOnce) {
    for (const ObjShape& shape : allShapes()) {
        SCOPED_TRACE(shape.name);
        const Built b = buildAll(shape);
        std::map<uint32_t, Evaluated> byPoint;
        for (uint32_t d = 0; d < b.domains.domainCount(); ++d) {
            if (b.domains.isHole(d)) continue;
            for (uint32_t c = 0; c < 4; ++c) {
                const Evaluated at = canonical(b.mesh, d, shader::tsSubdivCornerPoint(c));
                auto [it, inserted] = byPoint.emplace(b.domains.corners(d)[c], at);
                EXPECT_TRUE(it->second == at) << "domain " << d << " corner " << c;
                const double gap = glm::distance(limitAt(b, at), limitAt(b, {d, shader::tsSubdivCornerPoint(c)}));
                EXPECT_LE(gap, 1e-6 * b.surface.boundsDiagonal()) << "domain " << d << " corner " << c;
            }
        }
    }
}

TEST(SubdivDomains, QuadsSplitOnlyWhenTheMeshHasNonQuads) {
    for (const ObjShape& shape : allShapes()) {
        SCOPED_TRACE(shape.name);
        const Built b = buildAll(shape);
        bool nonQuads = false;
        for (uint32_t size : shape.faceSizes) nonQuads = nonQuads || size != 4;
        EXPECT_EQ(b.domains.splitQuads(), nonQuads);
        EXPECT_EQ(b.domains.ptexFaceCount(), b.surface.ptexFaceCount());
        for (uint32_t f = 0; f < shape.faceCount(); ++f) EXPECT_EQ(b.domains.firstPtexFace(f), b.surface.firstPtexFace(f));
        uint32_t expected = 0;
        for (uint32_t size : shape.faceSizes) expected += size == 4 ? (nonQuads ? 4 : 1) : size;
        EXPECT_EQ(b.domains.domainCount(), expected);
    }
}

TEST(SubdivDomains, ClosedOnlyWithoutBoundariesOrHoles) {
    for (const ObjShape& shape : allShapes()) {
        const Built b = buildAll(shape);
        const bool expected = shape.name == "cube" || shape.name.rfind("cube_crease", 0) == 0 ||
                              shape.name.rfind("torus", 0) == 0 || shape.name == "pentagon_pyramid" ||
                              shape.name == "pentagon_pyramid_smoothtris" || shape.name == "catmark_cube.obj" ||
                              shape.name == "catmark_cube_corner4.obj" || shape.name == "catmark_cube_creases1.obj" ||
                              shape.name == "catmark_pyramid.obj" || shape.name == "catmark_smoothtris0.obj";
        EXPECT_EQ(b.domains.closed(), expected) << shape.name;
        EXPECT_EQ(b.mesh.closed, expected) << shape.name;
    }
}

TEST(SubdivDomains, RadiiAndExtraordinaryPoints) {
    // The cube: 8 valence-3 vertices, every corner 1/2 of a unit... of its
    // edge length, half of it the radius.
    const Built b = buildAll(fileShapes().at(0));
    ASSERT_EQ(b.shape.name, "catmark_cube.obj");
    uint32_t extraordinary = 0;
    for (const SubdivDomains::CornerPoint& c : b.domains.cornerPoints()) {
        extraordinary += c.extraordinary ? 1u : 0u;
        EXPECT_GT(c.radius, 0.0f);
    }
    EXPECT_EQ(extraordinary, 8u);
}

TEST(SubdivGpuMesh, QuadtreeFindsFarsPatch) {
    for (const ObjShape& shape : allShapes()) {
        SCOPED_TRACE(shape.name);
        const Built b = buildAll(shape);
        uint32_t mismatches = 0;
        for (uint32_t p = 0; p < b.mesh.ptexFaceCount; ++p)
            for (int i = 0; i < 16; ++i)
                for (int j = 0; j < 16; ++j) {
                    const glm::vec2 uv((i + 0.5f) / 16.0f, (j + 0.5f) / 16.0f);
                    std::optional<uint32_t> far = b.surface.findPatch(p, glm::dvec2(uv));
                    const uint32_t gpu = b.mesh.findPatch(p, uv);
                    if (far.value_or(TS_SUBDIV_EMPTY) != gpu) ++mismatches;
                }
        EXPECT_EQ(mismatches, 0u);
    }
}

TEST(SubdivGpuMesh, StencilsReproduceTheControlPointsAndAverageTheCorners) {
    for (const ObjShape& shape : allShapes()) {
        SCOPED_TRACE(shape.name);
        const Built b = buildAll(shape);
        const std::vector<glm::vec4> refined = b.mesh.refine(shape.positions);
        ASSERT_EQ(refined.size(), b.mesh.refinedPointCount());
        const std::span<const glm::vec3> cps = b.surface.controlPoints();
        double worst = 0.0;
        for (uint32_t i = 0; i < cps.size(); ++i) {
            worst = std::max(worst, double(glm::distance(glm::vec3(refined[i]), cps[i])));
            EXPECT_EQ(refined[i].w, 1.0f);
        }
        EXPECT_LE(worst, 1e-6 * b.surface.boundsDiagonal());
        const std::vector<glm::vec3> corners = b.domains.cornerPositions(shape.positions);
        for (uint32_t c = 0; c < corners.size(); ++c) {
            const glm::vec4& r = refined[b.mesh.controlPointCount + c];
            EXPECT_LE(glm::distance(glm::vec3(r), corners[c]), 1e-6 * b.surface.boundsDiagonal());
            EXPECT_EQ(r.w, b.domains.cornerPoints()[c].radius);
        }
    }
}

TEST(SubdivGpuMesh, ExtraordinaryPatchCornersAreMarked) {
    // Every Gregory end cap touches an extraordinary vertex on the cube;
    // no regular patch is marked at a corner that is one.
    const Built b = buildAll(fileShapes().at(0));
    for (const shader::SubdivPatch& patch : b.mesh.patches) {
        const uint32_t type = patch.data.x & 0xffu;
        const uint32_t corners = patch.data.x >> TS_SUBDIV_PATCH_EV_SHIFT;
        if (type == TS_SUBDIV_PATCH_GREGORY_BASIS) {
            EXPECT_NE(corners, 0u);
        }
        EXPECT_LE(std::popcount(corners), 1);
    }
}

} // namespace
} // namespace tessera::subdiv::test
