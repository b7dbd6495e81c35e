// The mesh-shader tessellation run on the CPU: assembling a patch from its
// pieces (TessMeshPattern.h compiled as C++, the task and mesh shaders' own
// code) and the library's connectivity must give exactly Tessellator's
// triangles for every level up to 64: at every boundary where a point count
// changes, and at 2,000 random levels. Every piece must fit one mesh
// workgroup on any device (the Vulkan minimum is 256 vertices and 256
// primitives; lavapipe and NVIDIA have exactly that).
#include "tessera/core/Random.h"
#include "tessera/shaders/TessMeshPattern.h"
#include "tessera/tessellator/MeshPatternLibrary.h"
#include "tessera/tessellator/Tessellator.h"
#include "QuadPatternTriangles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <vector>

using namespace tessera;
using namespace tessera::tessellator;

namespace {

using test::PatternTriangle;

std::vector<PatternTriangle> assembled(const TessFactors& f) {
    const MeshPatternLibrary& library = MeshPatternLibrary::quadFractionalOdd();
    const shader::TsMeshPatch patch = shader::tsMeshPatch(glm::vec4(f.outer[0], f.outer[1], f.outer[2], f.outer[3]),
                                                          glm::vec2(f.inner[0], f.inner[1]));
    EXPECT_LE(patch.pieceCount, TS_MESH_MAX_PIECES);
    std::vector<PatternTriangle> triangles;
    for (uint32_t piece = 0; piece < patch.pieceCount; ++piece) {
        const uint32_t key = shader::tsMeshPieceKey(patch, piece);
        EXPECT_LT(key, TS_MESH_KEY_COUNT);
        const glm::uvec4 entry = library.keys()[key].entry;
        for (uint32_t t = 0; t < entry.y; ++t) {
            const uint32_t packed = library.triangles()[entry.x + t];
            PatternTriangle triangle;
            for (uint32_t c = 0; c < 3; ++c) {
                const uint32_t local = (packed >> (8 * c)) & 0xffu;
                const uint32_t row = local < entry.z ? 0 : 1;
                EXPECT_LT(local, entry.z + entry.w);
                const glm::vec2 uv = shader::tsMeshPiecePoint(patch, piece, row, local - row * entry.z);
                triangle[c] = {uv.x, uv.y};
            }
            triangles.push_back(test::canonicalTriangle(triangle));
        }
    }
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

void expectSame(const TessFactors& f) {
    const auto expected = test::referenceQuadTriangles(f);
    const auto actual = assembled(f);
    ASSERT_EQ(actual.size(), expected.size()) << test::describeLevels(f);
    EXPECT_TRUE(actual == expected) << test::describeLevels(f);
}

} // namespace

TEST(TessellatorMeshPattern, EveryPieceFitsOneMeshWorkgroup) {
    const MeshPatternLibrary& library = MeshPatternLibrary::quadFractionalOdd();
    ASSERT_EQ(library.keys().size(), TS_MESH_KEY_COUNT);
    for (const shader::TsMeshKey& key : library.keys()) {
        EXPECT_GT(key.entry.y, 0u);
        EXPECT_LE(key.entry.y, TS_MESH_MAX_TRIANGLES);
        EXPECT_LE(key.entry.z + key.entry.w, TS_MESH_MAX_VERTICES);
        EXPECT_LE(key.entry.x + key.entry.y, library.triangles().size());
    }
    std::cout << "[mesh pattern] " << library.keys().size() << " keys, " << library.triangles().size()
              << " triangles\n";
    const shader::TsMeshPatch densest = shader::tsMeshPatch(glm::vec4(64.0f), glm::vec2(64.0f));
    EXPECT_EQ(densest.pieceCount, TS_MESH_MAX_PIECES);
}

// Every level where a point count changes (odd integers, just below and
// above), alone and mixed, on every edge and axis.
TEST(TessellatorMeshPattern, ClassBoundariesMatchTheTessellator) {
    const float nudge = 1.0f / 256.0f;
    for (int odd = 1; odd <= 63; odd += 2)
        for (float level : {float(odd) - nudge, float(odd), float(odd) + nudge}) {
            if (level < 1.0f) continue;
            expectSame({{level, level, level, level}, {level, level}});
            expectSame({{level, 1.0f, 64.0f, 7.0f}, {level, 3.0f}});
            expectSame({{2.0f, level, 9.0f, level}, {33.0f, level}});
            if (HasFailure()) return;
        }
}

TEST(TessellatorMeshPattern, RandomLevelsMatchTheTessellator) {
    Random rng(29u);
    for (int i = 0; i < 2000; ++i) {
        // A third of the levels land exactly on 1 or an odd integer.
        auto pick = [&] {
            switch (rng.below(6)) {
            case 0: return 1.0f;
            case 1: return float(2 * rng.below(32) + 1);
            default: return rng.range(0.5f, TS_MESH_MAX_LEVEL);
            }
        };
        TessFactors f;
        for (float& o : f.outer) o = pick();
        for (float& in : f.inner) in = pick();
        expectSame(f);
        if (HasFailure()) return;
    }
}

// The mesh stage draws consecutive pieces together (tsMeshPiecesPerGroup):
// every group must fit one workgroup, and low levels must take few groups.
TEST(TessellatorMeshPattern, PieceGroupsFitOneWorkgroup) {
    const MeshPatternLibrary& library = MeshPatternLibrary::quadFractionalOdd();
    Random rng(31u);
    uint32_t groups = 0, pieces = 0;
    for (int i = 0; i < 2000; ++i) {
        const float top = i < 1000 ? 16.0f : TS_MESH_MAX_LEVEL;
        const shader::TsMeshPatch p =
            shader::tsMeshPatch(glm::vec4(rng.range(1.0f, top), rng.range(1.0f, top), rng.range(1.0f, top),
                                          rng.range(1.0f, top)),
                                glm::vec2(rng.range(1.0f, top), rng.range(1.0f, top)));
        const uint32_t perGroup = shader::tsMeshPiecesPerGroup(p);
        ASSERT_GE(perGroup, 1u);
        for (uint32_t first = 0; first < p.pieceCount; first += perGroup) {
            uint32_t points = 0, triangles = 0;
            for (uint32_t piece = first; piece < std::min(first + perGroup, p.pieceCount); ++piece) {
                const glm::uvec4 entry = library.keys()[shader::tsMeshPieceKey(p, piece)].entry;
                points += entry.z + entry.w;
                triangles += entry.y;
            }
            EXPECT_LE(points, TS_MESH_MAX_VERTICES);
            EXPECT_LE(triangles, TS_MESH_MAX_TRIANGLES);
        }
        groups += shader::tsMeshGroupCount(p);
        pieces += p.pieceCount;
    }
    std::cout << "[mesh pattern] 2,000 patches: " << pieces << " pieces in " << groups << " mesh workgroups\n";
    // Level 8 everywhere (10 points an edge): 17 pieces in 3 workgroups;
    // level 4 (6 points): 9 pieces in one.
    const shader::TsMeshPatch eight = shader::tsMeshPatch(glm::vec4(8.0f), glm::vec2(8.0f));
    EXPECT_EQ(eight.pieceCount, 17u);
    EXPECT_EQ(shader::tsMeshGroupCount(eight), 3u);
    const shader::TsMeshPatch four = shader::tsMeshPatch(glm::vec4(4.0f), glm::vec2(4.0f));
    EXPECT_EQ(four.pieceCount, 9u);
    EXPECT_EQ(shader::tsMeshGroupCount(four), 1u);
}

TEST(TessellatorMeshPattern, MinimalAndFramedPatches) {
    expectSame({{1.0f, 1.0f, 1.0f, 1.0f}, {1.0f, 1.0f}});
    expectSame({{1.0f, 5.0f, 1.0f, 1.0f}, {1.0f, 1.0f}});
    expectSame({{1.0f, 1.0f, 1.0f, 1.0f}, {1.0f, 64.0f}});
    expectSame({{64.0f, 1.0f, 64.0f, 1.0f}, {1.0f, 1.0f}});
}
