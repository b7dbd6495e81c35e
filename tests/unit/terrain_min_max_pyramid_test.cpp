// MinMaxPyramid: the true displaced bounds of every patch and block of
// patches, and local updates that match a rebuild.

#include "tessera/terrain/MinMaxPyramid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace tessera::terrain;

namespace {

// Rolling hills plus per-sample noise from an integer hash, so every patch
// has its own extremes and some lie between samples' neighbours.
HeightField makeHills(uint32_t n) {
    std::vector<uint16_t> v(size_t(n) * n);
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t h = (i * 73856093u) ^ (j * 19349663u);
            h = (h ^ (h >> 13)) * 0x5bd1e995u;
            const double hills = 30000.0 + 15000.0 * std::sin(i * 0.11) * std::cos(j * 0.07);
            v[size_t(j) * n + i] = uint16_t(hills + double(h >> 20));
        }
    return HeightField(n, n, std::move(v), TerrainScale{4.0f, 600.0f});
}

void expectSamePyramid(const MinMaxPyramid& a, const MinMaxPyramid& b) {
    ASSERT_EQ(a.levelCount(), b.levelCount());
    for (uint32_t level = 0; level < a.levelCount(); ++level)
        for (uint32_t z = 0; z < a.levelSize(level); ++z)
            for (uint32_t x = 0; x < a.levelSize(level); ++x)
                EXPECT_EQ(a.minMax(level, x, z), b.minMax(level, x, z)) << level << ": " << x << "," << z;
}

} // namespace

TEST(TerrainMinMaxPyramid, LevelSizesHalveRoundingUp) {
    HeightField field = makeHills(129);
    PatchGrid odd(field, 5);
    MinMaxPyramid a(field, odd);
    ASSERT_EQ(a.levelCount(), 4u);
    EXPECT_EQ(a.levelSize(0), 5u);
    EXPECT_EQ(a.levelSize(1), 3u);
    EXPECT_EQ(a.levelSize(2), 2u);
    EXPECT_EQ(a.levelSize(3), 1u);
    PatchGrid one(field, 1);
    EXPECT_EQ(MinMaxPyramid(field, one).levelCount(), 1u);
    PatchGrid eight(field, 8);
    EXPECT_EQ(MinMaxPyramid(field, eight).levelCount(), 4u);
}

TEST(TerrainMinMaxPyramid, PatchBoundsHoldTheSurfaceDensely) {
    HeightField field = makeHills(129);
    for (uint32_t p : {4u, 5u, 7u}) {
        PatchGrid grid(field, p);
        MinMaxPyramid pyramid(field, grid);
        for (uint32_t patch = 0; patch < grid.patchCount(); ++patch) {
            const tessera::scene::Aabb box = pyramid.patchBounds(patch);
            const glm::vec2 lo = grid.patchOrigin(patch), size = grid.patchSize();
            EXPECT_FLOAT_EQ(box.min.x, lo.x);
            EXPECT_FLOAT_EQ(box.min.z, lo.y);
            EXPECT_NEAR(box.max.x, lo.x + size.x, 1e-3f);
            EXPECT_NEAR(box.max.z, lo.y + size.y, 1e-3f);
            // A quarter of a sample spacing apart, edges included.
            const int steps = int(std::ceil(size.x / 1.0f));
            for (int b = 0; b <= steps; ++b)
                for (int a = 0; a <= steps; ++a) {
                    const float h = field.heightAt(lo.x + size.x * float(a) / float(steps),
                                                   lo.y + size.y * float(b) / float(steps));
                    ASSERT_GE(h, box.min.y) << "patch " << patch;
                    ASSERT_LE(h, box.max.y) << "patch " << patch;
                }
        }
    }
}

TEST(TerrainMinMaxPyramid, TopLevelIsTheFieldsRangeAndParentsHoldChildren) {
    HeightField field = makeHills(129);
    PatchGrid grid(field, 5);
    MinMaxPyramid pyramid(field, grid);
    const uint32_t top = pyramid.levelCount() - 1;
    EXPECT_EQ(pyramid.minMax(top, 0, 0), field.minMaxHeight(0, 0, 128, 128));
    const tessera::scene::Aabb whole = pyramid.cellBounds(top, 0, 0);
    EXPECT_EQ(whole.min.x, 0.0f);
    EXPECT_EQ(whole.min.z, 0.0f);
    EXPECT_FLOAT_EQ(whole.max.x, field.worldSize().x);
    EXPECT_FLOAT_EQ(whole.max.z, field.worldSize().y);
    for (uint32_t level = 1; level <= top; ++level)
        for (uint32_t z = 0; z < pyramid.levelSize(level); ++z)
            for (uint32_t x = 0; x < pyramid.levelSize(level); ++x) {
                const tessera::scene::Aabb parent = pyramid.cellBounds(level, x, z);
                tessera::scene::Aabb children;
                for (uint32_t cz = 2 * z; cz < std::min(2 * z + 2, pyramid.levelSize(level - 1)); ++cz)
                    for (uint32_t cx = 2 * x; cx < std::min(2 * x + 2, pyramid.levelSize(level - 1)); ++cx)
                        children.expand(pyramid.cellBounds(level - 1, cx, cz));
                // Exactly the union: no slack, no gap.
                EXPECT_EQ(parent.min, children.min);
                EXPECT_EQ(parent.max, children.max);
            }
}

TEST(TerrainMinMaxPyramid, BoundsFollowARamp) {
    std::vector<uint16_t> v(129 * 129);
    for (uint32_t j = 0; j < 129; ++j)
        for (uint32_t i = 0; i < 129; ++i) v[j * 129 + i] = uint16_t(i * 65535u / 128);
    HeightField field(129, 129, std::move(v), TerrainScale{4.0f, 400.0f});
    PatchGrid grid(field, 4);
    MinMaxPyramid pyramid(field, grid);
    // The ramp rises along x: the first column of patches is lowest, the last highest.
    EXPECT_NEAR(pyramid.patchBounds(0).min.y, 0.0f, 1e-3f);
    EXPECT_NEAR(pyramid.patchBounds(0).max.y, 100.0f, 0.01f);
    EXPECT_NEAR(pyramid.patchBounds(3).max.y, 400.0f, 1e-3f);
    EXPECT_LE(pyramid.patchBounds(0).max.y, pyramid.patchBounds(1).min.y);
}

TEST(TerrainMinMaxPyramid, UpdateAfterAChangeMatchesARebuild) {
    HeightField field = makeHills(129);
    PatchGrid grid(field, 5);
    MinMaxPyramid pyramid(field, grid);
    // A tall spike and a deep pit in a small rectangle.
    const SampleRect changed{60, 30, 64, 33};
    for (uint32_t j = changed.j0; j <= changed.j1; ++j)
        for (uint32_t i = changed.i0; i <= changed.i1; ++i) field.setSample(i, j, (i + j) % 2 ? 65535 : 0);
    pyramid.update(grid.patchesTouching(changed));
    expectSamePyramid(pyramid, MinMaxPyramid(field, grid));
    EXPECT_EQ(pyramid.minMax(pyramid.levelCount() - 1, 0, 0), std::make_pair(0.0f, 600.0f));
    // An empty rectangle changes nothing.
    pyramid.update({});
    expectSamePyramid(pyramid, MinMaxPyramid(field, grid));
}
