// Meteor shower: a deterministic, sorted schedule of craters inside the
// region, spread over the window, aimed where asked.

#include "tessera/terrain/MeteorShower.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using namespace tessera::terrain;

namespace {

MeteorShowerSettings makeSettings() {
    MeteorShowerSettings s;
    s.count = 200;
    s.seed = 7;
    s.startSeconds = 3.0;
    s.durationSeconds = 4.0;
    s.minRadius = 35.0f;
    s.maxRadius = 110.0f;
    s.scatter = 450.0f;
    s.regionMin = {0.0f, 0.0f};
    s.regionMax = {8188.0f, 8188.0f};
    return s;
}

// The aim moves along +X with time, like a camera flying over the map.
glm::vec2 aimAt(double t) {
    return {1000.0f + 500.0f * float(t), 4000.0f};
}

bool sameImpact(const MeteorImpact& a, const MeteorImpact& b) {
    return a.timeSeconds == b.timeSeconds && a.splat.center == b.splat.center && a.splat.radius == b.splat.radius &&
           a.splat.profile.depth == b.splat.profile.depth && a.splat.profile.rimHeight == b.splat.profile.rimHeight &&
           a.splat.profile.rimAt == b.splat.profile.rimAt;
}

} // namespace

TEST(TerrainMeteorShower, SameSettingsGiveTheSameSchedule) {
    const auto a = scheduleMeteorShower(makeSettings(), aimAt);
    const auto b = scheduleMeteorShower(makeSettings(), aimAt);
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k) EXPECT_TRUE(sameImpact(a[k], b[k])) << k;
}

TEST(TerrainMeteorShower, ADifferentSeedGivesADifferentSchedule) {
    MeteorShowerSettings other = makeSettings();
    other.seed = 8;
    const auto a = scheduleMeteorShower(makeSettings(), aimAt);
    const auto b = scheduleMeteorShower(other, aimAt);
    ASSERT_EQ(a.size(), b.size());
    size_t differing = 0;
    for (size_t k = 0; k < a.size(); ++k) differing += !sameImpact(a[k], b[k]);
    EXPECT_GT(differing, a.size() / 2);
}

TEST(TerrainMeteorShower, ImpactsAreSortedInsideTheWindowRangeAndRegion) {
    const MeteorShowerSettings s = makeSettings();
    const auto impacts = scheduleMeteorShower(s, aimAt);
    ASSERT_EQ(impacts.size(), s.count);
    for (size_t k = 0; k < impacts.size(); ++k) {
        const MeteorImpact& m = impacts[k];
        if (k > 0) {
            EXPECT_LE(impacts[k - 1].timeSeconds, m.timeSeconds);
        }
        EXPECT_GE(m.timeSeconds, s.startSeconds);
        EXPECT_LT(m.timeSeconds, s.startSeconds + s.durationSeconds);
        const float r = m.splat.radius;
        EXPECT_GE(r, s.minRadius);
        EXPECT_LE(r, s.maxRadius);
        EXPECT_FLOAT_EQ(m.splat.profile.depth, 0.22f * r);
        EXPECT_FLOAT_EQ(m.splat.profile.rimHeight, 0.06f * r);
        EXPECT_FLOAT_EQ(m.splat.profile.rimAt, 0.7f);
        // Within scatter of the aim (the region is wide enough not to clamp here).
        EXPECT_LE(glm::length(m.splat.center - aimAt(m.timeSeconds)), s.scatter * 1.0001f) << k;
    }
    // Spread evenly: each quarter of the window gets about a quarter.
    uint32_t firstQuarter = 0;
    for (const MeteorImpact& m : impacts) firstQuarter += m.timeSeconds < s.startSeconds + s.durationSeconds / 4;
    EXPECT_EQ(firstQuarter, s.count / 4);
}

TEST(TerrainMeteorShower, CentresAreClampedIntoTheRegion) {
    MeteorShowerSettings s = makeSettings();
    s.regionMin = {100.0f, 200.0f};
    s.regionMax = {900.0f, 700.0f};
    // Aimed at a corner outside the region: every crater is pushed inside.
    const auto impacts = scheduleMeteorShower(s, [](double) { return glm::vec2(-300.0f, 1000.0f); });
    for (const MeteorImpact& m : impacts) {
        const float r = m.splat.radius;
        EXPECT_GE(m.splat.center.x, s.regionMin.x + r);
        EXPECT_LE(m.splat.center.x, s.regionMax.x - r);
        EXPECT_GE(m.splat.center.y, s.regionMin.y + r);
        EXPECT_LE(m.splat.center.y, s.regionMax.y - r);
    }
}

TEST(TerrainMeteorShower, NoImpactsWhenCountIsZero) {
    MeteorShowerSettings s = makeSettings();
    s.count = 0;
    EXPECT_TRUE(scheduleMeteorShower(s, aimAt).empty());
}
