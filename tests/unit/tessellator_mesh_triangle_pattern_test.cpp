// The mesh-shader tessellation of uniform-level triangle patches (characters
// and a crowd's near tier) run on the CPU: assembling a patch from its pieces
// (TessMeshTrianglePattern.h compiled as C++, the task and mesh shaders' own
// code) and the library's connectivity must give exactly Tessellator's
// triangles, bit for bit, for every level up to 64: at every boundary where
// the point count changes, and at 2,000 random levels. Every piece must fit
// one mesh workgroup on any device (the Vulkan minimum is 256 vertices and
// 256 primitives).
#include "TrianglePatternTriangles.h"
#include "tessera/core/Random.h"
#include "tessera/shaders/TessMeshTrianglePattern.h"
#include "tessera/tessellator/MeshTrianglePatternLibrary.h"
#include "tessera/tessellator/Tessellator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace tessera;
using namespace tessera::tessellator;

namespace {

using test::PatternTriangle;

std::vector<PatternTriangle> assembled(float level) {
    const MeshTrianglePatternLibrary& library = MeshTrianglePatternLibrary::uniformFractionalOdd();
    const shader::TsMeshTrianglePatch patch = shader::tsMeshTrianglePatch(level);
    EXPECT_LE(patch.pieceCount, TS_MESH_TRI_MAX_PIECES);
    std::vector<PatternTriangle> triangles;
    for (uint32_t piece = 0; piece < patch.pieceCount; ++piece) {
        const uint32_t key = shader::tsMeshTrianglePieceKey(patch, piece);
        EXPECT_LT(key, TS_MESH_TRI_KEY_COUNT);
        if (key >= TS_MESH_TRI_KEY_COUNT) return {};
        const glm::uvec4 entry = library.keys()[key].entry;
        for (uint32_t t = 0; t < entry.y; ++t) {
            const uint32_t packed = library.triangles()[entry.x + t];
            PatternTriangle triangle;
            for (uint32_t c = 0; c < 3; ++c) {
                const uint32_t local = (packed >> (8 * c)) & 0xffu;
                const uint32_t row = local < entry.z ? 0 : 1;
                EXPECT_LT(local, entry.z + entry.w);
                const glm::vec3 uvw = shader::tsMeshTrianglePiecePoint(patch, piece, row, local - row * entry.z);
                EXPECT_EQ(uvw.z, 1.0f - uvw.x - uvw.y);
                triangle[c] = {uvw.x, uvw.y};
            }
            triangles.push_back(test::canonicalTriangle(triangle));
        }
    }
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

void expectSame(float level) {
    const auto expected = test::referenceTriangleTriangles(level);
    const auto actual = assembled(level);
    ASSERT_EQ(actual.size(), expected.size()) << "level " << level;
    EXPECT_TRUE(actual == expected) << "level " << level;
}

} // namespace

TEST(TessellatorMeshTrianglePattern, EveryPieceFitsOneMeshWorkgroup) {
    const MeshTrianglePatternLibrary& library = MeshTrianglePatternLibrary::uniformFractionalOdd();
    ASSERT_EQ(library.keys().size(), TS_MESH_TRI_KEY_COUNT);
    for (const shader::TsMeshKey& key : library.keys()) {
        EXPECT_GT(key.entry.y, 0u);
        EXPECT_LE(key.entry.y, TS_MESH_MAX_TRIANGLES);
        EXPECT_LE(key.entry.z + key.entry.w, TS_MESH_MAX_VERTICES);
        EXPECT_LE(key.entry.x + key.entry.y, library.triangles().size());
        for (uint32_t t = 0; t < key.entry.y; ++t) {
            const uint32_t packed = library.triangles()[key.entry.x + t];
            EXPECT_EQ(packed >> 24, 0u);
            for (uint32_t c = 0; c < 3; ++c) EXPECT_LT((packed >> (8 * c)) & 0xffu, key.entry.z + key.entry.w);
        }
    }
    EXPECT_EQ(shader::tsMeshTrianglePatch(64.0f).pieceCount, TS_MESH_TRI_MAX_PIECES);
    EXPECT_EQ(shader::tsMeshTrianglePatch(1.0f).pieceCount, 1u);
}

// Every level where the point count changes (odd integers, just below and
// above, by 1/256 and by one float step), the even integers between them,
// and the clamped ends.
TEST(TessellatorMeshTrianglePattern, ClassBoundariesMatchTheTessellator) {
    const float nudge = 1.0f / 256.0f;
    std::vector<float> levels = {0.5f, 1.0f + 1.0f / 65536.0f, 1.0f + 1.0f / 131072.0f, 64.0f, 100.0f};
    for (int odd = 1; odd <= 63; odd += 2) {
        const float boundary = float(odd);
        for (float level : {boundary - nudge, boundary, boundary + nudge, std::nextafter(boundary, 0.0f),
                            std::nextafter(boundary, 100.0f), boundary + 1.0f})
            if (level >= 1.0f) levels.push_back(level);
    }
    for (float level : levels) {
        expectSame(level);
        if (HasFailure()) return;
    }
}

TEST(TessellatorMeshTrianglePattern, RandomLevelsMatchTheTessellator) {
    Random rng(31u);
    for (int i = 0; i < 2000; ++i) {
        // A sixth of the levels land exactly on an odd integer.
        const float level = rng.below(6) == 0 ? float(2 * rng.below(32) + 1) : rng.range(1.0f, TS_MESH_MAX_LEVEL);
        expectSame(level);
        if (HasFailure()) return;
    }
}

// A negative control: the pieces of one level placed at a level of another
// class are not that level's pattern, so the comparison can fail.
TEST(TessellatorMeshTrianglePattern, AnotherClassDoesNotMatch) {
    EXPECT_NE(assembled(9.0f).size(), test::referenceTriangleTriangles(11.0f).size());
    EXPECT_FALSE(assembled(10.0f) == test::referenceTriangleTriangles(9.5f));
}

// The group table the mesh stage draws by: for every point class, the
// groups' chains cover every piece once, each group within one workgroup's
// limits with its chains' shared rows counted once, and small patches share
// a workgroup.
TEST(TessellatorMeshTrianglePattern, GroupsCoverEveryPieceWithinAWorkgroup) {
    const MeshTrianglePatternLibrary& library = MeshTrianglePatternLibrary::uniformFractionalOdd();
    for (const bool crowd : {false, true}) {
    SCOPED_TRACE(crowd ? "crowd groups" : "groups");
    const auto table = crowd ? library.crowdGroups() : library.groups();
    const uint32_t maxTriangles = crowd ? TS_MESH_MAX_TRIANGLES : TS_MESH_TRI_GROUP_MAX_TRIANGLES;
    ASSERT_GE(table.size(), TS_MESH_TRI_CLASSES);
    uint32_t points15 = 0, triangles15 = 0;
    for (uint32_t c = 0; c < TS_MESH_TRI_CLASSES; ++c) {
        SCOPED_TRACE("class " + std::to_string(c));
        const float level = c == 0 ? 1.0f : float(2 * c + 1);
        const shader::TsMeshTrianglePatch p = shader::tsMeshTrianglePatch(level);
        EXPECT_EQ(p.points / 2 - 1, c);
        const glm::uvec4 info = table[c];
        ASSERT_GE(info.y, 1u);
        ASSERT_GE(info.z, 1u);
        std::vector<int> seen(p.pieceCount, 0);
        uint32_t patchTriangles = 0;
        for (uint32_t g = 0; g < info.y; ++g) {
            const glm::uvec4 group = table[info.x + g];
            uint32_t points = 0, triangles = 0;
            for (uint32_t k = 0; k < group.y; ++k) {
                const glm::uvec4 chain = table[group.x + k];
                if (chain.x == TS_MESH_TRI_CHAIN_CENTRE) {
                    ++seen[p.pieceCount - 1];
                    points += 3;
                    triangles += 1;
                    continue;
                }
                ASSERT_LE(chain.y, chain.z);
                for (uint32_t q = chain.y; q <= chain.z; ++q) {
                    const uint32_t piece = 3 * q + chain.x;
                    ASSERT_LT(piece, p.pieceCount);
                    ++seen[piece];
                    triangles += library.keys()[shader::tsMeshTrianglePieceKey(p, piece)].entry.y;
                }
                for (uint32_t r = chain.y; r <= chain.z + 1; ++r) points += p.points - 2 * r;
            }
            EXPECT_EQ(points, group.z);
            EXPECT_EQ(triangles, group.w);
            EXPECT_LE(group.z * info.z, TS_MESH_MAX_VERTICES);
            EXPECT_LE(group.w * info.z, maxTriangles);
            patchTriangles += triangles;
            if (c == 7) {
                points15 += points;
                triangles15 += triangles;
            }
        }
        for (uint32_t piece = 0; piece < p.pieceCount; ++piece) EXPECT_EQ(seen[piece], 1) << "piece " << piece;
        EXPECT_EQ(patchTriangles, Tessellator::countTriangles(Domain::Triangle, Partitioning::FractionalOdd,
                                                              {{level, level, level, 0.0f}, {level, 0.0f}}));
    }
    // Level 15 (16 points an edge): 337 triangles from 229 evaluated points
    // (three edge chains of 72 points and the centre, one chain cut where a
    // workgroup fills, repeating a 10-point row); a piece a workgroup
    // evaluated 381.
    EXPECT_EQ(triangles15, 337u);
    if (!crowd) EXPECT_EQ(points15, 229u);
    }
}
