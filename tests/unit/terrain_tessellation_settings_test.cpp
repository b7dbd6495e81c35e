// TessellationSettings: names for the command line and reports, and the enum
// values the shaders receive.

#include "tessera/terrain/TessellationSettings.h"

#include "tessera/shaders/TessFactors.h"

#include <gtest/gtest.h>

#include <string>

using namespace tessera::terrain;

TEST(TerrainTessellationSettings, ModeNamesRoundTrip) {
    for (TerrainMode mode : {TerrainMode::LowRes, TerrainMode::Continuous, TerrainMode::Adaptive})
        EXPECT_EQ(parseTerrainMode(toString(mode)), mode);
    EXPECT_STREQ(toString(TerrainMode::LowRes), "lowres");
    EXPECT_STREQ(toString(TerrainMode::Continuous), "continuous");
    EXPECT_STREQ(toString(TerrainMode::Adaptive), "adaptive");
}

TEST(TerrainTessellationSettings, MetricNamesRoundTrip) {
    for (TessMetric metric :
         {TessMetric::ScreenEdge, TessMetric::Distance, TessMetric::Silhouette, TessMetric::HeightDetail})
        EXPECT_EQ(parseTessMetric(toString(metric)), metric);
    EXPECT_STREQ(toString(TessMetric::ScreenEdge), "screen");
    EXPECT_STREQ(toString(TessMetric::Distance), "distance");
    EXPECT_STREQ(toString(TessMetric::Silhouette), "silhouette");
    EXPECT_STREQ(toString(TessMetric::HeightDetail), "detail");
}

TEST(TerrainTessellationSettings, BadNamesAreRejected) {
    for (const char* bad : {"", "Adaptive", "adaptive ", "low-res", "screen", "tiles"})
        EXPECT_EQ(parseTerrainMode(bad), std::nullopt) << bad;
    for (const char* bad : {"", "Screen", "detail ", "height", "adaptive"})
        EXPECT_EQ(parseTessMetric(bad), std::nullopt) << bad;
}

TEST(TerrainTessellationSettings, ValuesMatchTheShaderIds) {
    EXPECT_EQ(uint32_t(TerrainMode::LowRes), TS_TERRAIN_MODE_LOWRES);
    EXPECT_EQ(uint32_t(TerrainMode::Continuous), TS_TERRAIN_MODE_CONTINUOUS);
    EXPECT_EQ(uint32_t(TerrainMode::Adaptive), TS_TERRAIN_MODE_ADAPTIVE);
    EXPECT_EQ(uint32_t(TessMetric::ScreenEdge), TS_METRIC_SCREEN);
    EXPECT_EQ(uint32_t(TessMetric::Distance), TS_METRIC_DISTANCE);
    EXPECT_EQ(uint32_t(TessMetric::Silhouette), TS_METRIC_SILHOUETTE);
    EXPECT_EQ(uint32_t(TessMetric::HeightDetail), TS_METRIC_DETAIL);
}
