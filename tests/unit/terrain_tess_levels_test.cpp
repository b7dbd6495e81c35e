// computeTessLevels: the CPU reference of the GPU factor pre-pass. One level
// per canonical edge, so neighbours agree; clamps; each metric's behaviour.

#include "tessera/terrain/Terrain.h"
#include "tessera/terrain/TessLevels.h"

#include "tessera/shaders/TessFactors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

using namespace tessera::terrain;

namespace {

constexpr uint32_t kSize = 129; // 128 spacings of 4 m: 512 m

HeightField makeField(uint16_t (*value)(uint32_t, uint32_t)) {
    std::vector<uint16_t> v(size_t(kSize) * kSize);
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) v[size_t(j) * kSize + i] = value(i, j);
    return HeightField(kSize, kSize, std::move(v), TerrainScale{4.0f, 600.0f});
}

uint16_t flat(uint32_t, uint32_t) {
    return 10000;
}

// A ridge along Z at sample column 48, inside patch column 1 of a 4 x 4 grid.
uint16_t ridge(uint32_t i, uint32_t) {
    return uint16_t(10000 + std::max(0, 20000 - 4000 * std::abs(int(i) - 48)));
}

uint16_t hills(uint32_t i, uint32_t j) {
    return uint16_t(20000.0 + 12000.0 * std::sin(i * 0.08) * std::cos(j * 0.06));
}

TessellationSettings adaptive(TessMetric metric) {
    TessellationSettings s;
    s.mode = TerrainMode::Adaptive;
    s.metric = metric;
    s.targetPixels = 8.0f;
    s.minLevel = 2.0f;
    s.maxLevel = 64.0f;
    return s;
}

const TessView kOverhead{{256.0f, 400.0f, 256.0f}, 540.0f};

} // namespace

TEST(TerrainTessLevels, OneLevelPerEdgeSharedByNeighbours) {
    Terrain t(makeField(hills), 4);
    const TessLevels levels = computeTessLevels(t, adaptive(TessMetric::ScreenEdge), kOverhead, 64.0f);
    ASSERT_EQ(levels.edges.size(), t.grid().edgeCount());
    ASSERT_EQ(levels.patches.size(), t.grid().patchCount());
    const PatchGrid& grid = t.grid();
    for (uint32_t z = 0; z < 4; ++z)
        for (uint32_t x = 0; x + 1 < 4; ++x) {
            const auto left = grid.patchEdges(z * 4 + x), right = grid.patchEdges(z * 4 + x + 1);
            EXPECT_EQ(levels.edges[left[2]], levels.edges[right[0]]);
        }
    // Each edge's level is the metric on its canonical endpoints at ground height.
    for (uint32_t e = 0; e < grid.edgeCount(); ++e) {
        const auto ends = grid.edgeEndpoints(e);
        const glm::vec3 a{ends[0].x, t.heightAt(ends[0].x, ends[0].y), ends[0].y};
        const glm::vec3 b{ends[1].x, t.heightAt(ends[1].x, ends[1].y), ends[1].y};
        const float expected = tessera::shader::tsScreenEdgeLevel(a, b, kOverhead.eye, kOverhead.pixelsPerMetre, 8.0f);
        EXPECT_FLOAT_EQ(levels.edges[e], std::clamp(expected, 2.0f, 64.0f)) << e;
    }
}

TEST(TerrainTessLevels, FlatGroundWithTheDetailMetricStaysAtTheMinimum) {
    Terrain t(makeField(flat), 4);
    const TessLevels levels = computeTessLevels(t, adaptive(TessMetric::HeightDetail), kOverhead, 64.0f);
    for (float level : levels.edges) EXPECT_EQ(level, 2.0f);
    for (float level : levels.patches) EXPECT_EQ(level, 2.0f);
}

TEST(TerrainTessLevels, RidgesGetMoreThanTheMinimumWithTheDetailMetric) {
    Terrain t(makeField(ridge), 4);
    const TessLevels levels = computeTessLevels(t, adaptive(TessMetric::HeightDetail), kOverhead, 64.0f);
    const PatchGrid& grid = t.grid();
    for (uint32_t e = 0; e < grid.edgeCount(); ++e) {
        const auto ends = grid.edgeEndpoints(e);
        const bool crossing = ends[0].y == ends[1].y && ends[0].x == 128.0f;
        if (crossing) {
            EXPECT_GT(levels.edges[e], 4.0f) << e;
        } else {
            EXPECT_EQ(levels.edges[e], 2.0f) << e;
        }
    }
    for (uint32_t p = 0; p < grid.patchCount(); ++p) {
        if (p % 4 == 1) {
            EXPECT_GT(levels.patches[p], 4.0f) << p;
        } else {
            EXPECT_EQ(levels.patches[p], 2.0f) << p;
        }
    }
    // The patch level is the detail metric over the patch's opposite corners.
    const uint32_t p = 2 * 4 + 1;
    const glm::vec2 lo = grid.patchOrigin(p), hi = lo + grid.patchSize();
    const float expected =
        tessera::shader::tsDetailLevel({lo.x, t.heightAt(lo.x, lo.y), lo.y}, {hi.x, t.heightAt(hi.x, hi.y), hi.y},
                                       kOverhead.eye, t.detail().patchError()[p], kOverhead.pixelsPerMetre, 8.0f);
    EXPECT_FLOAT_EQ(levels.patches[p], std::clamp(expected, 2.0f, 64.0f));
    // Inner levels take the rough interior even where the edges are smooth.
    const auto inner = innerLevels(levels, grid, p);
    EXPECT_EQ(inner[1], levels.patches[p]);
}

TEST(TerrainTessLevels, ScreenEdgeLevelHalvesWhenTheDistanceDoubles) {
    Terrain t(makeField(flat), 4);
    TessellationSettings s = adaptive(TessMetric::ScreenEdge);
    s.minLevel = 1.0f;
    const uint32_t edge = t.grid().patchEdges(5)[1];
    const auto ends = t.grid().edgeEndpoints(edge);
    const glm::vec2 middle = (ends[0] + ends[1]) * 0.5f;
    const float ground = t.heightAt(middle.x, middle.y);
    const TessView nearView{{middle.x, ground + 300.0f, middle.y}, 1000.0f};
    const TessView farView{{middle.x, ground + 600.0f, middle.y}, 1000.0f};
    const float nearLevel = computeTessLevels(t, s, nearView, 64.0f).edges[edge];
    const float farLevel = computeTessLevels(t, s, farView, 64.0f).edges[edge];
    EXPECT_GT(nearLevel, 8.0f);
    EXPECT_LT(nearLevel, 64.0f);
    EXPECT_NEAR(farLevel / nearLevel, 0.5f, 0.005f);
}

TEST(TerrainTessLevels, DistanceAndSilhouetteMetrics) {
    Terrain t(makeField(flat), 4);
    TessellationSettings s = adaptive(TessMetric::Distance);
    s.farDistance = 600.0f;
    // Eye at the -X,-Z corner, on the ground: levels fall with distance.
    const TessView corner{{0.0f, t.heightAt(0.0f, 0.0f), 0.0f}, 540.0f};
    const TessLevels distance = computeTessLevels(t, s, corner, 64.0f);
    const uint32_t nearEdge = t.grid().patchEdges(0)[1], farEdge = t.grid().patchEdges(15)[3];
    EXPECT_GT(distance.edges[nearEdge], 50.0f);
    EXPECT_EQ(distance.edges[farEdge], 2.0f);
    // Flat ground seen from straight above faces the viewer everywhere: a
    // quarter of the screen-space level.
    const TessLevels screen = computeTessLevels(t, adaptive(TessMetric::ScreenEdge), kOverhead, 64.0f);
    const TessLevels silhouette = computeTessLevels(t, adaptive(TessMetric::Silhouette), kOverhead, 64.0f);
    for (uint32_t e = 0; e < t.grid().edgeCount(); ++e)
        EXPECT_LE(silhouette.edges[e], std::max(screen.edges[e] * 0.26f, 2.0f)) << e;
    for (float level : silhouette.patches) EXPECT_EQ(level, 0.0f);
}

TEST(TerrainTessLevels, ContinuousAndLowResModes) {
    Terrain t(makeField(hills), 4);
    TessellationSettings s;
    s.mode = TerrainMode::Continuous;
    s.continuousLevel = 15.0f;
    TessLevels levels = computeTessLevels(t, s, kOverhead, 64.0f);
    for (float level : levels.edges) EXPECT_EQ(level, 15.0f);
    for (float level : levels.patches) EXPECT_EQ(level, 0.0f);
    EXPECT_EQ(innerLevels(levels, t.grid(), 6), (std::array<float, 2>{15.0f, 15.0f}));
    s.continuousLevel = 100.0f;
    for (float level : computeTessLevels(t, s, kOverhead, 14.99f).edges) EXPECT_EQ(level, 14.99f);
    s.continuousLevel = 0.25f;
    for (float level : computeTessLevels(t, s, kOverhead, 64.0f).edges) EXPECT_EQ(level, 1.0f);

    s.mode = TerrainMode::LowRes;
    levels = computeTessLevels(t, s, kOverhead, 64.0f);
    for (float level : levels.edges) EXPECT_EQ(level, 1.0f);
    for (float level : levels.patches) EXPECT_EQ(level, 1.0f);
}

TEST(TerrainTessLevels, AdaptiveLevelsClampToTheBackendAndSettings) {
    Terrain t(makeField(hills), 4);
    TessellationSettings s = adaptive(TessMetric::ScreenEdge);
    const TessView close{{256.0f, 200.0f, 256.0f}, 1e6f}; // absurdly fine: every edge at the maximum
    for (float level : computeTessLevels(t, s, close, 16.0f).edges) EXPECT_EQ(level, 16.0f);
    s.maxLevel = 10.0f;
    for (float level : computeTessLevels(t, s, close, 64.0f).edges) EXPECT_EQ(level, 10.0f);
    // Coarse: every edge at the minimum, itself clamped to [1, maxLevel].
    const TessView far{{256.0f, 200.0f, 256.0f}, 1e-3f};
    s.minLevel = 0.25f;
    for (float level : computeTessLevels(t, s, far, 64.0f).edges) EXPECT_EQ(level, 1.0f);
    s.minLevel = 30.0f;
    for (float level : computeTessLevels(t, s, far, 64.0f).edges) EXPECT_EQ(level, 10.0f);
}

TEST(TerrainTessLevels, InnerLevelsTakeTheOppositeEdgesAndPatchLevel) {
    Terrain t(makeField(hills), 4);
    TessLevels levels = computeTessLevels(t, adaptive(TessMetric::ScreenEdge), kOverhead, 64.0f);
    const auto e = t.grid().patchEdges(9);
    levels.edges[e[0]] = 3.0f;
    levels.edges[e[1]] = 7.0f;
    levels.edges[e[2]] = 5.0f;
    levels.edges[e[3]] = 4.0f;
    levels.patches[9] = 0.0f;
    EXPECT_EQ(innerLevels(levels, t.grid(), 9), (std::array<float, 2>{7.0f, 5.0f}));
    levels.patches[9] = 6.0f;
    EXPECT_EQ(innerLevels(levels, t.grid(), 9), (std::array<float, 2>{7.0f, 6.0f}));
}

TEST(TerrainTessLevels, LevelsAreDeterministic) {
    Terrain t(makeField(hills), 5);
    for (TessMetric metric :
         {TessMetric::ScreenEdge, TessMetric::Distance, TessMetric::Silhouette, TessMetric::HeightDetail}) {
        const TessLevels a = computeTessLevels(t, adaptive(metric), kOverhead, 64.0f);
        const TessLevels b = computeTessLevels(t, adaptive(metric), kOverhead, 64.0f);
        EXPECT_EQ(a.edges, b.edges);
        EXPECT_EQ(a.patches, b.patches);
    }
}
