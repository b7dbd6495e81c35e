// TerrainDetail: how far the height field strays from the straight edges and
// flat patches of the control mesh: zero on planes, large across ridges.

#include "tessera/terrain/TerrainDetail.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <functional>

using namespace tessera::terrain;

namespace {

constexpr uint32_t kSize = 129; // 128 spacings of 4 m: 512 m

HeightField makeField(const std::function<uint16_t(uint32_t, uint32_t)>& value) {
    std::vector<uint16_t> v(size_t(kSize) * kSize);
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) v[size_t(j) * kSize + i] = value(i, j);
    return HeightField(kSize, kSize, std::move(v), TerrainScale{4.0f, 600.0f});
}

// A tilted plane: bilinear interpolation reproduces it exactly.
HeightField makePlane() {
    return makeField([](uint32_t i, uint32_t j) { return uint16_t(1000 + 37 * i + 53 * j); });
}

// A ridge along Z at sample column 48, in the middle of patch column 1 of a
// 4 x 4 grid (columns of 32 samples), ten samples wide, on flat ground.
HeightField makeRidge() {
    return makeField([](uint32_t i, uint32_t j) {
        (void)j;
        const int d = std::abs(int(i) - 48);
        return uint16_t(1000 + std::max(0, 20000 - 4000 * d));
    });
}

} // namespace

TEST(TerrainDetail, PlanarGroundHasNoError) {
    HeightField field = makePlane();
    for (uint32_t p : {4u, 5u}) {
        PatchGrid grid(field, p);
        TerrainDetail detail(field, grid);
        ASSERT_EQ(detail.edgeError().size(), grid.edgeCount());
        ASSERT_EQ(detail.patchError().size(), grid.patchCount());
        for (float e : detail.edgeError()) EXPECT_LT(e, 1e-3f);
        for (float e : detail.patchError()) EXPECT_LT(e, 1e-3f);
    }
}

TEST(TerrainDetail, ARidgeGivesLargeErrorWhereItCrosses) {
    HeightField field = makeRidge();
    PatchGrid grid(field, 4);
    TerrainDetail detail(field, grid);
    const float peak = 20000.0f / 65535.0f * 600.0f; // ~183 m above the plain
    for (uint32_t patch = 0; patch < grid.patchCount(); ++patch) {
        const bool crossed = patch % 4 == 1;
        if (crossed) {
            EXPECT_NEAR(detail.patchError()[patch], peak, 1.0f) << patch;
        } else {
            EXPECT_LT(detail.patchError()[patch], 1e-3f) << patch;
        }
    }
    for (uint32_t e = 0; e < grid.edgeCount(); ++e) {
        const auto ends = grid.edgeEndpoints(e);
        // Edges along X in column 1 cut through the ridge; every other edge
        // lies on flat ground or along a grid line beside the ridge.
        const bool crossing = ends[0].y == ends[1].y && ends[0].x == 128.0f;
        if (crossing) {
            EXPECT_NEAR(detail.edgeError()[e], peak, 1.0f) << e;
        } else {
            EXPECT_LT(detail.edgeError()[e], 1e-3f) << e;
        }
    }
}

TEST(TerrainDetail, UpdateAfterAChangeMatchesARebuild) {
    HeightField field = makePlane();
    PatchGrid grid(field, 5);
    TerrainDetail detail(field, grid);
    const SampleRect changed{40, 70, 47, 75};
    for (uint32_t j = changed.j0; j <= changed.j1; ++j)
        for (uint32_t i = changed.i0; i <= changed.i1; ++i) field.setSample(i, j, uint16_t(200 * i + 90 * j));
    detail.update(grid.patchesTouching(changed));
    TerrainDetail rebuilt(field, grid);
    EXPECT_EQ(detail.edgeError(), rebuilt.edgeError());
    EXPECT_EQ(detail.patchError(), rebuilt.patchError());
    float worst = 0.0f;
    for (float e : detail.patchError()) worst = std::max(worst, e);
    EXPECT_GT(worst, 1.0f);
}
