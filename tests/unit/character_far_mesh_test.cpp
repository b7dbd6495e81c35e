// character::simplifyCage: the far LOD tier's mesh. A cube sphere cut into UV
// charts stands in for a generated creature's cage: closed once welded, with
// seam copies along every chart border. One chart per cube face lets the
// seam-preserving pass reach the target; 16 per face locks it (as the
// froblins' atlases do) and the welded pass takes over.
#include "tessera/character/FarMesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>

namespace {

using namespace tessera;
using character::CageMesh;
using character::CageVertex;
using character::FarMeshMethod;

// A unit sphere from a cube of `n` x `n` quads per face, each face cut into
// `charts` x `charts` UV charts. Positions come from integer lattice points,
// so seam copies are bitwise equal. uv.x names the chart: floor(uv.x * total).
CageMesh makeChartedSphere(int n, int charts) {
    struct Face {
        glm::vec3 normal, u, v;  // u x v = normal, so the quads face outwards
    };
    const Face faces[6] = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                           {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
                           {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
    const int h = n / 2;
    const int totalCharts = 6 * charts * charts;
    CageMesh cage;
    cage.bindings = {{0, glm::mat4(1.0f)}, {1, glm::mat4(1.0f)}};
    for (int f = 0; f < 6; ++f) {
        for (int ca = 0; ca < charts; ++ca) {
            for (int cb = 0; cb < charts; ++cb) {
                const int chart = (f * charts + ca) * charts + cb;
                const int a0 = ca * n / charts, a1 = (ca + 1) * n / charts;
                const int b0 = cb * n / charts, b1 = (cb + 1) * n / charts;
                std::map<std::pair<int, int>, uint32_t> ids;  // this chart's own vertices
                auto vertex = [&](int a, int b) {
                    auto [it, inserted] = ids.emplace(std::make_pair(a, b), static_cast<uint32_t>(cage.vertices.size()));
                    if (inserted) {
                        glm::vec3 lattice = faces[f].normal * float(h) + faces[f].u * float(a - h) + faces[f].v * float(b - h);
                        CageVertex v;
                        v.position = glm::normalize(lattice);
                        v.normal = v.position;
                        v.tangent = glm::vec4(faces[f].u, 1.0f);
                        float lu = float(a - a0) / float(a1 - a0), lv = float(b - b0) / float(b1 - b0);
                        v.uv = {(float(chart) + 0.25f + 0.5f * lu) / float(totalCharts), lv};
                        v.joints = {v.position.y < 0.0f ? 0 : 1, 0, 0, 0};
                        v.weights = {1, 0, 0, 0};
                        cage.vertices.push_back(v);
                    }
                    return it->second;
                };
                for (int a = a0; a < a1; ++a) {
                    for (int b = b0; b < b1; ++b) {
                        uint32_t q0 = vertex(a, b), q1 = vertex(a + 1, b), q2 = vertex(a + 1, b + 1), q3 = vertex(a, b + 1);
                        cage.indices.insert(cage.indices.end(), {q0, q1, q2, q0, q2, q3});
                    }
                }
            }
        }
    }
    return cage;
}

int chartOf(const CageVertex& v, int totalCharts) { return static_cast<int>(std::floor(v.uv.x * float(totalCharts))); }

// Edges counted by welded position: {edges used once (boundary), edges used
// more than twice or not matched (non-manifold)}.
std::pair<size_t, size_t> openEdges(const CageMesh& mesh) {
    std::map<std::array<float, 3>, uint32_t> weld;
    auto id = [&](uint32_t v) {
        const glm::vec3& p = mesh.vertices[v].position;
        return weld.emplace(std::array<float, 3>{p.x, p.y, p.z}, static_cast<uint32_t>(weld.size())).first->second;
    };
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        for (size_t k = 0; k < 3; ++k) {
            uint32_t a = id(mesh.indices[t + k]), b = id(mesh.indices[t + (k + 1) % 3]);
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    size_t boundary = 0, nonManifold = 0;
    for (const auto& [edge, count] : uses) {
        if (count == 1) ++boundary;
        else if (count != 2) ++nonManifold;
    }
    return {boundary, nonManifold};
}

bool sameVertex(const CageVertex& a, const CageVertex& b) {
    return a.position == b.position && a.normal == b.normal && a.tangent == b.tangent && a.uv == b.uv &&
           a.joints == b.joints && a.weights == b.weights;
}

struct Case {
    const char* name;
    int charts;
    FarMeshMethod expected;
};

const Case kCases[] = {{"one chart per face", 1, FarMeshMethod::SeamPreserving},
                       {"16 charts per face", 4, FarMeshMethod::Welded}};

TEST(CharacterFarMesh, MeetsTheTargetWithTheExpectedMethod) {
    for (const Case& c : kCases) {
        CageMesh cage = makeChartedSphere(24, c.charts);
        ASSERT_EQ(cage.triangleCount(), 6912u);
        auto far = character::simplifyCage(cage);
        ASSERT_TRUE(far.ok()) << far.error().message;
        std::printf("%s: %u -> %u triangles, %zu vertices, %s, error %.4f (%.4f units), %u seam triangles\n", c.name,
                    cage.triangleCount(), far->mesh.triangleCount(), far->mesh.vertices.size(),
                    character::farMeshMethodName(far->method), far->relativeError, far->absoluteError,
                    far->seamTriangles);
        EXPECT_EQ(far->method, c.expected) << c.name;
        EXPECT_LE(far->mesh.triangleCount(), 300u) << c.name;
        EXPECT_GE(far->mesh.triangleCount(), 200u) << c.name;
    }
}

TEST(CharacterFarMesh, UsesEveryVertexAndCopiesThemFromTheCage) {
    for (const Case& c : kCases) {
        CageMesh cage = makeChartedSphere(24, c.charts);
        auto far = character::simplifyCage(cage);
        ASSERT_TRUE(far.ok()) << far.error().message;
        const CageMesh& mesh = far->mesh;
        std::vector<bool> used(mesh.vertices.size(), false);
        for (uint32_t i : mesh.indices) {
            ASSERT_LT(i, mesh.vertices.size());
            used[i] = true;
        }
        EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << c.name;
        for (size_t v = 0; v < mesh.vertices.size(); ++v) {
            bool found = std::any_of(cage.vertices.begin(), cage.vertices.end(),
                                     [&](const CageVertex& x) { return sameVertex(x, mesh.vertices[v]); });
            EXPECT_TRUE(found) << c.name << ": far vertex " << v << " is not a cage vertex";
        }
        ASSERT_EQ(mesh.bindings.size(), cage.bindings.size());
        for (size_t b = 0; b < cage.bindings.size(); ++b) {
            EXPECT_EQ(mesh.bindings[b].node, cage.bindings[b].node);
            EXPECT_EQ(mesh.bindings[b].inverseBind, cage.bindings[b].inverseBind);
        }
    }
}

TEST(CharacterFarMesh, ClosedCageStaysClosed) {
    for (const Case& c : kCases) {
        CageMesh cage = makeChartedSphere(24, c.charts);
        ASSERT_EQ(openEdges(cage), std::make_pair(size_t{0}, size_t{0}));
        auto far = character::simplifyCage(cage);
        ASSERT_TRUE(far.ok()) << far.error().message;
        auto [boundary, nonManifold] = openEdges(far->mesh);
        EXPECT_EQ(boundary, 0u) << c.name;
        EXPECT_EQ(nonManifold, 0u) << c.name;
    }
}

TEST(CharacterFarMesh, SeamPreservingKeepsEveryTriangleInOneChart) {
    const int charts = 1, total = 6;
    CageMesh cage = makeChartedSphere(24, charts);
    auto far = character::simplifyCage(cage);
    ASSERT_TRUE(far.ok()) << far.error().message;
    ASSERT_EQ(far->method, FarMeshMethod::SeamPreserving);
    EXPECT_EQ(far->seamTriangles, 0u);
    const CageMesh& m = far->mesh;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        int chart = chartOf(m.vertices[m.indices[t]], total);
        EXPECT_EQ(chartOf(m.vertices[m.indices[t + 1]], total), chart);
        EXPECT_EQ(chartOf(m.vertices[m.indices[t + 2]], total), chart);
    }
}

TEST(CharacterFarMesh, WeldedPassKeepsMostTrianglesInOneChart) {
    const int charts = 4, total = 6 * 16;
    CageMesh cage = makeChartedSphere(24, charts);
    auto far = character::simplifyCage(cage);
    ASSERT_TRUE(far.ok()) << far.error().message;
    ASSERT_EQ(far->method, FarMeshMethod::Welded);
    const CageMesh& m = far->mesh;
    uint32_t mixed = 0;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
        int chart = chartOf(m.vertices[m.indices[t]], total);
        if (chartOf(m.vertices[m.indices[t + 1]], total) != chart || chartOf(m.vertices[m.indices[t + 2]], total) != chart)
            ++mixed;
    }
    EXPECT_EQ(mixed, far->seamTriangles);
    EXPECT_LT(far->seamTriangles, m.triangleCount());
}

TEST(CharacterFarMesh, ErrorIsBoundedAndMatchesTheSurface) {
    character::FarMeshSettings settings;
    for (const Case& c : kCases) {
        CageMesh cage = makeChartedSphere(24, c.charts);
        auto far = character::simplifyCage(cage, settings);
        ASSERT_TRUE(far.ok()) << far.error().message;
        EXPECT_GT(far->relativeError, 0.0f) << c.name;
        EXPECT_LE(far->relativeError, settings.maxError) << c.name;
        // The sphere spans 2 units, meshoptimizer's scale for it.
        EXPECT_NEAR(far->absoluteError, far->relativeError * 2.0f, 1e-5f) << c.name;
        // Every vertex is on the unit sphere; the flat triangles sag inside it.
        // meshoptimizer's error is a quadric estimate, not a Hausdorff
        // distance, so allow a small multiple of it (about 1.6x seen).
        float sag = 0.0f;
        const CageMesh& m = far->mesh;
        for (size_t t = 0; t < m.indices.size(); t += 3) {
            glm::vec3 centre = (m.vertices[m.indices[t]].position + m.vertices[m.indices[t + 1]].position +
                                m.vertices[m.indices[t + 2]].position) / 3.0f;
            sag = std::max(sag, 1.0f - glm::length(centre));
        }
        std::printf("%s: largest sag %.4f, reported error %.4f\n", c.name, sag, far->absoluteError);
        EXPECT_LE(sag, 3.0f * far->absoluteError) << c.name;
    }
}

TEST(CharacterFarMesh, IsDeterministic) {
    for (const Case& c : kCases) {
        CageMesh cage = makeChartedSphere(24, c.charts);
        auto a = character::simplifyCage(cage);
        auto b = character::simplifyCage(cage);
        ASSERT_TRUE(a.ok() && b.ok());
        EXPECT_EQ(a->mesh.indices, b->mesh.indices);
        ASSERT_EQ(a->mesh.vertices.size(), b->mesh.vertices.size());
        EXPECT_EQ(std::memcmp(a->mesh.vertices.data(), b->mesh.vertices.data(), a->mesh.vertices.size() * sizeof(CageVertex)), 0);
        EXPECT_EQ(a->relativeError, b->relativeError);
    }
}

TEST(CharacterFarMesh, FallsBackToClusteringWhenNoCollapseFitsTheError) {
    CageMesh cage = makeChartedSphere(24, 4);
    character::FarMeshSettings settings;
    settings.maxError = 0.0f;  // no edge collapse on a sphere is free
    auto far = character::simplifyCage(cage, settings);
    ASSERT_TRUE(far.ok()) << far.error().message;
    EXPECT_EQ(far->method, FarMeshMethod::Sloppy);
    EXPECT_LE(far->mesh.triangleCount(), settings.targetTriangles);
    EXPECT_GT(far->mesh.triangleCount(), 0u);
}

TEST(CharacterFarMesh, SmallCageIsCopiedWithoutUnusedVertices) {
    CageMesh cage = makeChartedSphere(4, 1);  // 192 triangles
    cage.vertices.push_back(CageVertex{});    // unused
    auto far = character::simplifyCage(cage);
    ASSERT_TRUE(far.ok()) << far.error().message;
    EXPECT_EQ(far->method, FarMeshMethod::Copy);
    EXPECT_EQ(far->mesh.triangleCount(), cage.triangleCount());
    EXPECT_EQ(far->mesh.vertices.size(), cage.vertices.size() - 1);
    EXPECT_EQ(far->relativeError, 0.0f);
}

TEST(CharacterFarMesh, RejectsBadInputWithOneLine) {
    auto expectError = [](const CageMesh& cage, const character::FarMeshSettings& settings, const std::string& text) {
        auto far = character::simplifyCage(cage, settings);
        ASSERT_FALSE(far.ok());
        EXPECT_NE(far.error().message.find(text), std::string::npos) << far.error().message;
        EXPECT_EQ(far.error().message.find('\n'), std::string::npos);
    };
    character::FarMeshSettings settings;
    expectError(CageMesh{}, settings, "no triangles");
    CageMesh cage = makeChartedSphere(8, 1);
    CageMesh bad = cage;
    bad.indices[7] = 100000;
    expectError(bad, settings, "cage index 7 (100000) is beyond");
    bad = cage;
    bad.indices.pop_back();
    expectError(bad, settings, "not a multiple of 3");
    bad = cage;
    bad.vertices[3].position.x = std::nanf("");
    expectError(bad, settings, "vertex 3 has a non-finite position");
    character::FarMeshSettings zero;
    zero.targetTriangles = 0;
    expectError(cage, zero, "target triangle count is 0");
}

} // namespace
