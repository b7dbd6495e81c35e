// PatchGrid: the control mesh's geometry, the canonical edge numbering that
// makes shared edges one stored factor, and the sample ranges patches depend on.

#include "tessera/terrain/PatchGrid.h"

#include "tessera/shaders/TerrainPatches.h"

#include <gtest/gtest.h>

#include <set>

using namespace tessera::terrain;

namespace {

HeightField makeFlat(uint32_t n, float spacing = 4.0f) {
    return HeightField(n, n, std::vector<uint16_t>(size_t(n) * n, 1000), TerrainScale{spacing, 600.0f});
}

bool intersects(const SampleRect& a, const SampleRect& b) {
    return !a.empty() && !b.empty() && a.i0 <= b.i1 && b.i0 <= a.i1 && a.j0 <= b.j1 && b.j0 <= a.j1;
}

} // namespace

TEST(TerrainPatchGrid, SizesAndOrigins) {
    HeightField field = makeFlat(129);
    PatchGrid grid(field, 5);
    EXPECT_EQ(grid.patchesPerSide(), 5u);
    EXPECT_EQ(grid.patchCount(), 25u);
    EXPECT_EQ(grid.edgeCount(), 2u * 5u * 6u);
    EXPECT_FLOAT_EQ(grid.patchSize().x, 512.0f / 5.0f);
    EXPECT_FLOAT_EQ(grid.patchSize().y, 512.0f / 5.0f);
    const glm::vec2 origin = grid.patchOrigin(2 * 5 + 3);
    EXPECT_FLOAT_EQ(origin.x, 3.0f * 512.0f / 5.0f);
    EXPECT_FLOAT_EQ(origin.y, 2.0f * 512.0f / 5.0f);
}

TEST(TerrainPatchGrid, SharedEdgesHaveOneIndexAndEveryEdgeIsUsed) {
    HeightField field = makeFlat(129);
    for (uint32_t p : {1u, 2u, 5u, 8u}) {
        PatchGrid grid(field, p);
        std::vector<uint32_t> uses(grid.edgeCount(), 0);
        for (uint32_t z = 0; z < p; ++z)
            for (uint32_t x = 0; x < p; ++x) {
                const auto edges = grid.patchEdges(z * p + x);
                EXPECT_EQ(std::set<uint32_t>(edges.begin(), edges.end()).size(), 4u);
                for (uint32_t side = 0; side < 4; ++side) {
                    ASSERT_LT(edges[side], grid.edgeCount());
                    EXPECT_EQ(edges[side], tessera::shader::tsPatchEdge(x, z, side, p));
                    ++uses[edges[side]];
                }
                // The +X side of a patch is the -X side of its right neighbour,
                // and its +Z side the -Z side of the one above.
                if (x + 1 < p) {
                    EXPECT_EQ(edges[2], grid.patchEdges(z * p + x + 1)[0]);
                }
                if (z + 1 < p) {
                    EXPECT_EQ(edges[3], grid.patchEdges((z + 1) * p + x)[1]);
                }
            }
        // Interior edges belong to two patches, border edges to one.
        uint32_t border = 0;
        for (uint32_t u : uses) {
            EXPECT_TRUE(u == 1 || u == 2);
            border += u == 1;
        }
        EXPECT_EQ(border, 4 * p) << "P = " << p;
    }
}

TEST(TerrainPatchGrid, EdgeEndpointsRunInTheCanonicalDirection) {
    HeightField field = makeFlat(129);
    const uint32_t p = 5;
    PatchGrid grid(field, p);
    const glm::vec2 size = grid.patchSize();
    for (uint32_t z = 0; z < p; ++z)
        for (uint32_t x = 0; x < p; ++x) {
            const uint32_t patch = z * p + x;
            const glm::vec2 lo = grid.patchOrigin(patch);
            const glm::vec2 hi = glm::vec2(float(x + 1), float(z + 1)) * size;
            const auto edges = grid.patchEdges(patch);
            // Per side: first and second endpoint.
            const glm::vec2 expected[4][2] = {
                {lo, {lo.x, hi.y}}, {lo, {hi.x, lo.y}}, {{hi.x, lo.y}, hi}, {{lo.x, hi.y}, hi}};
            for (uint32_t side = 0; side < 4; ++side) {
                const auto ends = grid.edgeEndpoints(edges[side]);
                EXPECT_EQ(ends[0], expected[side][0]) << "patch " << patch << " side " << side;
                EXPECT_EQ(ends[1], expected[side][1]) << "patch " << patch << " side " << side;
            }
        }
    // Edges along X come first, then edges along Z.
    for (uint32_t e = 0; e < grid.edgeCount(); ++e) {
        const auto ends = grid.edgeEndpoints(e);
        if (e < p * (p + 1)) {
            EXPECT_EQ(ends[0].y, ends[1].y);
            EXPECT_LT(ends[0].x, ends[1].x);
        } else {
            EXPECT_EQ(ends[0].x, ends[1].x);
            EXPECT_LT(ends[0].y, ends[1].y);
        }
    }
}

TEST(TerrainPatchGrid, PatchSamplesSpanTheInterpolatedSamples) {
    HeightField field = makeFlat(129);
    // Aligned: 128 spacings over 4 patches, 32 each; neighbours share a column.
    PatchGrid aligned(field, 4);
    const SampleRect first = aligned.patchSamples(0);
    EXPECT_EQ(first.i0, 0u);
    EXPECT_EQ(first.i1, 32u);
    EXPECT_EQ(first.j0, 0u);
    EXPECT_EQ(first.j1, 32u);
    const SampleRect last = aligned.patchSamples(15);
    EXPECT_EQ(last.i0, 96u);
    EXPECT_EQ(last.i1, 128u);
    // Not aligned: 25.6 spacings per patch, floor to ceil.
    PatchGrid grid(field, 5);
    const SampleRect s = grid.patchSamples(1 * 5 + 2);
    EXPECT_EQ(s.i0, 51u);
    EXPECT_EQ(s.i1, 77u);
    EXPECT_EQ(s.j0, 25u);
    EXPECT_EQ(s.j1, 52u);
    // Clamped to the field at the far side.
    EXPECT_EQ(grid.patchSamples(24).i1, 128u);
    EXPECT_EQ(grid.patchSamples(24).j1, 128u);
}

TEST(TerrainPatchGrid, PatchesTouchingMatchesBruteForce) {
    HeightField field = makeFlat(129);
    for (uint32_t p : {1u, 3u, 4u, 5u, 7u}) {
        PatchGrid grid(field, p);
        EXPECT_TRUE(grid.patchesTouching({}).empty());
        uint32_t state = 12345;
        auto next = [&](uint32_t limit) {
            state = state * 1664525u + 1013904223u;
            return (state >> 8) % limit;
        };
        for (int trial = 0; trial < 200; ++trial) {
            const uint32_t i0 = next(129), j0 = next(129);
            const SampleRect rect{i0, j0, std::min(128u, i0 + next(20)), std::min(128u, j0 + next(20))};
            const SampleRect touching = grid.patchesTouching(rect);
            ASSERT_FALSE(touching.empty());
            for (uint32_t z = 0; z < p; ++z)
                for (uint32_t x = 0; x < p; ++x)
                    EXPECT_EQ(touching.contains(x, z), intersects(grid.patchSamples(z * p + x), rect))
                        << "P " << p << " patch " << x << "," << z << " rect " << rect.i0 << "," << rect.j0 << ".."
                        << rect.i1 << "," << rect.j1;
        }
    }
}
