// The procedural height-map generator: same settings, same bytes (whatever
// the thread count), full 0..65535 range, and well-formed progress reports.

#include "tessera/terrain/HeightMapGenerator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace tessera::terrain;

namespace {

HeightMapGeneratorSettings smallSettings(uint32_t size, uint64_t seed, uint32_t threads) {
    HeightMapGeneratorSettings settings;
    settings.size = size;
    settings.seed = seed;
    settings.threadCount = threads;
    return settings;
}

} // namespace

TEST(TerrainHeightMapGenerator, SameSeedGivesIdenticalSamples) {
    const auto first = generateHeightMap(smallSettings(128, 7, 2));
    const auto second = generateHeightMap(smallSettings(128, 7, 2));
    ASSERT_EQ(first.size(), 128u * 128u);
    EXPECT_TRUE(first == second);
}

TEST(TerrainHeightMapGenerator, ThreadCountNeverChangesTheOutput) {
    // 512 has 4x4 erosion tiles, so several tiles of one colour run at once,
    // and a 128 coarse pass: every parallel path is exercised.
    const auto single = generateHeightMap(smallSettings(512, 3, 1));
    const auto many = generateHeightMap(smallSettings(512, 3, 5));
    EXPECT_TRUE(single == many);
}

TEST(TerrainHeightMapGenerator, DifferentSeedsGiveDifferentLandscapes) {
    const auto a = generateHeightMap(smallSettings(64, 1, 1));
    const auto b = generateHeightMap(smallSettings(64, 2, 1));
    size_t differing = 0;
    for (size_t k = 0; k < a.size(); ++k) differing += a[k] != b[k];
    EXPECT_GT(differing, a.size() / 2);
}

TEST(TerrainHeightMapGenerator, OutputSpansTheFullRange) {
    for (uint32_t size : {64u, 256u}) {
        const auto samples = generateHeightMap(smallSettings(size, 11, 2));
        auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
        EXPECT_EQ(*lo, 0) << size;
        EXPECT_EQ(*hi, 65535) << size;
    }
}

TEST(TerrainHeightMapGenerator, ErosionChangesTheTerrain) {
    auto settings = smallSettings(128, 5, 2);
    const auto eroded = generateHeightMap(settings);
    settings.erosionDroplets = 0;
    settings.thermalIterations = 0;
    const auto raw = generateHeightMap(settings);
    EXPECT_FALSE(eroded == raw);
}

TEST(TerrainHeightMapGenerator, ReportsMonotonicProgressThroughEveryStage) {
    std::vector<std::string> stages;
    float last = -1.0f;
    bool monotonic = true;
    generateHeightMap(smallSettings(128, 1, 3), [&](std::string_view stage, float fraction) {
        monotonic = monotonic && fraction >= last && fraction >= 0.0f && fraction <= 1.0f;
        last = fraction;
        if (stages.empty() || stages.back() != stage) stages.emplace_back(stage);
    });
    EXPECT_TRUE(monotonic);
    EXPECT_FLOAT_EQ(last, 1.0f);
    const std::vector<std::string> expected = {"terrain noise", "hydraulic erosion",
                                               "thermal erosion", "normalise"};
    EXPECT_EQ(stages, expected);
}

TEST(TerrainHeightMapGenerator, DefaultDropletsScaleWithArea) {
    EXPECT_EQ(defaultErosionDroplets(2048), 1048576u);
    EXPECT_EQ(defaultErosionDroplets(1024), 262144u);
}
