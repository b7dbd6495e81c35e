// The paper's two level modes: continuous (one level per draw, 1 to 14.99)
// and adaptive (per-edge levels clamped to a per-draw range).
#include "tessera/tessellator/AdaptiveLevels.h"
#include "tessera/tessellator/ContinuousLevel.h"

#include <gtest/gtest.h>

#include <limits>

using namespace tessera::tessellator;

TEST(TessellatorLevels, ContinuousClampsToTheD3D10Range) {
    EXPECT_EQ(ContinuousLevel::clamp(0.0f), 1.0f);
    EXPECT_EQ(ContinuousLevel::clamp(-5.0f), 1.0f);
    EXPECT_EQ(ContinuousLevel::clamp(std::numeric_limits<float>::quiet_NaN()), 1.0f);
    EXPECT_EQ(ContinuousLevel::clamp(7.25f), 7.25f);
    EXPECT_EQ(ContinuousLevel::clamp(14.99f), 14.99f);
    EXPECT_EQ(ContinuousLevel::clamp(64.0f), 14.99f);
    const TessFactors f = ContinuousLevel::factors(20.0f);
    for (float o : f.outer) EXPECT_EQ(o, 14.99f);
    for (float i : f.inner) EXPECT_EQ(i, 14.99f);
}

TEST(TessellatorLevels, AdaptiveClampsEachLevelToTheDrawRange) {
    auto levels = AdaptiveLevels::create(2.0f, 10.0f);
    ASSERT_TRUE(levels.ok()) << levels.error().message;
    EXPECT_EQ(levels->clamp(1.0f), 2.0f);
    EXPECT_EQ(levels->clamp(0.0f), 2.0f); // adaptive levels never cull
    EXPECT_EQ(levels->clamp(std::numeric_limits<float>::quiet_NaN()), 2.0f);
    EXPECT_EQ(levels->clamp(5.5f), 5.5f);
    EXPECT_EQ(levels->clamp(30.0f), 10.0f);
    const TessFactors f = levels->clamp(TessFactors{{0.5f, 3.0f, 12.0f, 10.0f}, {1.0f, 64.0f}});
    EXPECT_EQ(f.outer, (std::array<float, 4>{2.0f, 3.0f, 10.0f, 10.0f}));
    EXPECT_EQ(f.inner, (std::array<float, 2>{2.0f, 10.0f}));
}

TEST(TessellatorLevels, AdaptiveRejectsABadRange) {
    for (auto [lo, hi] : {std::pair{0.5f, 4.0f}, std::pair{5.0f, 4.0f}, std::pair{1.0f, 65.0f},
                          std::pair{std::numeric_limits<float>::quiet_NaN(), 4.0f}}) {
        auto levels = AdaptiveLevels::create(lo, hi);
        ASSERT_FALSE(levels.ok());
        EXPECT_NE(levels.error().message.find("adaptive tessellation levels"), std::string::npos);
    }
    EXPECT_TRUE(AdaptiveLevels::create(14.99f, 14.99f).ok());
}
