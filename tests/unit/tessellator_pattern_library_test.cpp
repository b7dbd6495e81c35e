// The emulated tessellator's GPU half, run on the CPU: for any levels of the
// D3D10-era range, selecting a pattern piece per edge and placing its points
// with the shaders' own code (TessPattern.h compiled as C++) must give
// exactly Tessellator's triangles, which the GPU tests show are the
// hardware's.
#include "tessera/core/Random.h"
#include "tessera/shaders/TessPattern.h"
#include "tessera/tessellator/PatternLibrary.h"
#include "tessera/tessellator/Tessellator.h"
#include "QuadPatternTriangles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

using namespace tessera;
using namespace tessera::tessellator;

namespace {

using test::canonicalTriangle;
using Triangle = test::PatternTriangle;

std::vector<Triangle> emulated(const TessFactors& f, uint32_t& commands) {
    const PatternLibrary& library = PatternLibrary::quadFractionalOdd();
    glm::uvec4 outer;
    glm::uvec2 inner;
    shader::tsEmuFixedLevels(glm::vec4(f.outer[0], f.outer[1], f.outer[2], f.outer[3]),
                             glm::vec2(f.inner[0], f.inner[1]), outer, inner);
    std::vector<Triangle> triangles;
    commands = 0;
    for (uint32_t piece = 0; piece < TS_EMU_PIECES; ++piece) {
        const uint32_t key = shader::tsEmuPieceKey(outer, inner, piece);
        if (key == TS_EMU_KEY_NONE) continue;
        EXPECT_LT(key, TS_EMU_KEY_COUNT);
        ++commands;
        const PatternLibrary::Piece p = library.pieces()[key];
        for (uint32_t v = 0; v < p.vertexCount; v += 3) {
            Triangle t;
            for (uint32_t c = 0; c < 3; ++c) {
                const glm::vec2 uv = shader::tsEmuDomainPoint(library.vertices()[p.firstVertex + v + c], piece, outer, inner);
                t[c] = {uv.x, uv.y};
            }
            triangles.push_back(canonicalTriangle(t));
        }
    }
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

void expectSame(const TessFactors& f) {
    uint32_t commands = 0;
    const auto expected = test::referenceQuadTriangles(f);
    const auto actual = emulated(f, commands);
    ASSERT_EQ(actual.size(), expected.size()) << test::describeLevels(f);
    EXPECT_TRUE(actual == expected) << test::describeLevels(f);
    EXPECT_EQ(actual.size(), Tessellator::countTriangles(Domain::Quad, Partitioning::FractionalOdd, f));
}

} // namespace

TEST(TessellatorPatternLibrary, EveryKeyHasTriangles) {
    const PatternLibrary& library = PatternLibrary::quadFractionalOdd();
    ASSERT_EQ(library.pieces().size(), TS_EMU_KEY_COUNT);
    for (const auto& piece : library.pieces()) {
        EXPECT_GT(piece.vertexCount, 0u);
        EXPECT_EQ(piece.vertexCount % 3, 0u);
        EXPECT_LE(piece.firstVertex + piece.vertexCount, library.vertices().size());
    }
}

TEST(TessellatorPatternLibrary, UniformLevelsMatchTheTessellator) {
    for (float level : {1.0f, 1.0001f, 1.5f, 2.0f, 2.999f, 3.0f, 3.001f, 4.7f, 7.5f, 9.0f, 13.0f, 14.5f, 14.99f})
        expectSame({{level, level, level, level}, {level, level}});
}

TEST(TessellatorPatternLibrary, MixedLevelsMatchTheTessellator) {
    Random rng(4u);
    auto level = [](Random& r) { return r.range(0.5f, TS_EMU_MAX_LEVEL); };
    auto special = [](Random& r) { return int(r.below(6)); };
    for (int i = 0; i < 3000; ++i) {
        TessFactors f;
        // Some levels exactly 1 or exactly odd integers: the edges of the
        // pattern classes, where a count changes.
        auto pick = [&] {
            switch (special(rng)) {
            case 0: return 1.0f;
            case 1: return float(2 * rng.below(7) + 1);
            default: return level(rng);
            }
        };
        for (float& o : f.outer) o = pick();
        for (float& in : f.inner) in = pick();
        expectSame(f);
        if (HasFailure()) break;
    }
}

TEST(TessellatorPatternLibrary, InnerLevelsBelowOneWithHigherEdgesKeepAFrame) {
    expectSame({{1.0f, 5.0f, 1.0f, 1.0f}, {1.0f, 1.0f}});
    expectSame({{1.0f, 1.0f, 1.0f, 1.0f}, {1.0f, 14.99f}});
    expectSame({{14.99f, 1.0f, 14.99f, 1.0f}, {1.0f, 1.0f}});
}
