// The emulated tessellator's triangle patterns at one uniform level (a crowd's
// near tier on the r2vb and streamout backends), run on the CPU: placing a
// class's point codes at a level with the shaders' own code
// (TessTrianglePattern.h compiled as C++) must give exactly Tessellator's
// points and triangles for that level, which the GPU tests show are the
// hardware's.
#include "tessera/shaders/TessTrianglePattern.h"
#include "tessera/core/Random.h"
#include "tessera/tessellator/ContinuousLevel.h"
#include "tessera/tessellator/Tessellator.h"
#include "tessera/tessellator/TrianglePatternLibrary.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <vector>

using namespace tessera;
using namespace tessera::tessellator;

namespace {

// Compares the library's pattern at `level` with Tessellator's, point for
// point (bit-identical floats) and index for index. Returns false and
// records a failure on the first difference.
bool matchesTessellator(float level) {
    const TrianglePatternLibrary& library = TrianglePatternLibrary::fractionalOdd();
    const uint32_t fxp = shader::tsEmuTriangleLevel(level);
    const uint32_t k = shader::tsEmuTriangleClass(fxp);
    EXPECT_LT(k, library.classes().size());
    if (k >= library.classes().size()) return false;
    const TrianglePatternLibrary::Class& c = library.classes()[k];
    const TessellatedPatch reference =
        Tessellator::tessellate(Domain::Triangle, Partitioning::FractionalOdd, ContinuousLevel::factors(level));
    EXPECT_EQ(c.codeCount, reference.uv.size()) << "level " << level;
    EXPECT_EQ(c.indexCount, reference.indices.size()) << "level " << level;
    if (c.codeCount != reference.uv.size() || c.indexCount != reference.indices.size()) return false;
    for (uint32_t i = 0; i < c.codeCount; ++i) {
        const glm::vec2 placed = shader::tsEmuTrianglePoint(library.codes()[c.firstCode + i], fxp);
        if (std::bit_cast<uint32_t>(placed.x) != std::bit_cast<uint32_t>(reference.uv[i].x) ||
            std::bit_cast<uint32_t>(placed.y) != std::bit_cast<uint32_t>(reference.uv[i].y)) {
            ADD_FAILURE() << "level " << level << " point " << i << ": placed (" << placed.x << ", " << placed.y
                          << "), tessellator (" << reference.uv[i].x << ", " << reference.uv[i].y << ")";
            return false;
        }
    }
    for (uint32_t i = 0; i < c.indexCount; ++i) {
        if (library.indices()[c.firstIndex + i] != reference.indices[i]) {
            ADD_FAILURE() << "level " << level << " index " << i << " differs";
            return false;
        }
    }
    return true;
}

} // namespace

// Every class at its ends, its middle and just inside its boundaries.
TEST(TrianglePatternLibrary, EveryClassMatchesTheTessellatorAtItsBoundaries) {
    const TrianglePatternLibrary& library = TrianglePatternLibrary::fractionalOdd();
    ASSERT_EQ(library.classes().size(), TS_EMU_TRIANGLE_CLASSES);
    std::vector<float> levels = {1.0f, 1.0f + 1.0f / 65536.0f, 1.0001f, 14.99f, 20.0f, 0.5f, NAN};
    for (int odd = 1; odd <= 13; odd += 2) {
        const float boundary = float(odd);
        levels.push_back(boundary);
        levels.push_back(std::nextafter(boundary, 0.0f));
        levels.push_back(std::nextafter(boundary, 100.0f));
        levels.push_back(boundary + 1.0f);
    }
    for (float level : levels) EXPECT_TRUE(matchesTessellator(level)) << level;
}

// Random continuous levels over the whole range.
TEST(TrianglePatternLibrary, RandomLevelsMatchTheTessellator) {
    Random random(20261125u);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const float level = 1.0f + random.nextFloat() * 13.99f;
        if (!matchesTessellator(level)) break;
        ++checked;
    }
    EXPECT_EQ(checked, 2000);
}

// The class of a level is the pattern the hardware would use: its triangle
// count is Tessellator's count at that level.
TEST(TrianglePatternLibrary, ClassesCountTheTessellatorsTriangles) {
    const TrianglePatternLibrary& library = TrianglePatternLibrary::fractionalOdd();
    for (float level = 1.0f; level <= 14.99f; level += 0.37f) {
        const uint32_t k = shader::tsEmuTriangleClass(shader::tsEmuTriangleLevel(level));
        EXPECT_EQ(
            library.classes()[k].indexCount / 3,
            Tessellator::countTriangles(Domain::Triangle, Partitioning::FractionalOdd, ContinuousLevel::factors(level)))
            << level;
    }
    // A negative control: placing a class's codes at a level of another
    // class does not reproduce that level's pattern.
    const auto& c3 = library.classes()[3];
    const TessellatedPatch at9 =
        Tessellator::tessellate(Domain::Triangle, Partitioning::FractionalOdd, ContinuousLevel::factors(9.0f));
    EXPECT_NE(c3.codeCount, at9.uv.size());
}
