// Crater splats: the CPU copy changes exactly where and how the shared
// formula says, and the Terrain keeps bounds, detail and the GPU queue in step.

#include "tessera/terrain/CraterSplat.h"
#include "tessera/terrain/Terrain.h"

#include "tessera/shaders/CraterProfile.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>

using namespace tessera::terrain;

namespace {

constexpr uint32_t kSize = 129;
constexpr float kSpacing = 4.0f;
constexpr float kHeightScale = 600.0f;

HeightField makeFlat(uint16_t value = 30000) {
    return HeightField(kSize, kSize, std::vector<uint16_t>(size_t(kSize) * kSize, value),
                       TerrainScale{kSpacing, kHeightScale});
}

HeightField makeHills() {
    std::vector<uint16_t> v(size_t(kSize) * kSize);
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i)
            v[size_t(j) * kSize + i] = uint16_t(30000.0 + 9000.0 * std::sin(i * 0.09) * std::cos(j * 0.05));
    return HeightField(kSize, kSize, std::move(v), TerrainScale{kSpacing, kHeightScale});
}

CraterSplat makeSplat() {
    CraterSplat splat;
    splat.center = {256.3f, 250.7f};
    splat.radius = 60.0f;
    splat.profile = {14.0f, 4.0f, 0.7f};
    return splat;
}

// The squared distance exactly as applyCrater and the GPU pass compute it.
float distanceSq(uint32_t i, uint32_t j, const CraterSplat& s) {
    const float dx = float(i) * kSpacing - s.center.x, dz = float(j) * kSpacing - s.center.y;
    return dx * dx + dz * dz;
}

} // namespace

TEST(TerrainCraterSplat, ChangesOnlySamplesInsideTheRadiusByTheSharedFormula) {
    HeightField field = makeHills();
    const std::vector<uint16_t> before = field.samples();
    const CraterSplat splat = makeSplat();
    const SampleRect rect = applyCrater(field, splat);
    EXPECT_FALSE(rect.empty());
    const tessera::shader::CraterSplatParams params{{splat.center.x, splat.center.y, splat.radius, kSpacing},
                                                    {14.0f, 4.0f, 0.7f, kHeightScale}};
    uint32_t inside = 0;
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) {
            const size_t k = size_t(j) * kSize + i;
            const float d2 = distanceSq(i, j, splat);
            if (d2 >= splat.radius * splat.radius) {
                ASSERT_EQ(field.samples()[k], before[k]) << i << "," << j;
                continue;
            }
            ++inside;
            EXPECT_TRUE(rect.contains(i, j));
            const int expected = std::clamp(int(before[k]) + tessera::shader::tsCraterDelta(d2, params), 0, 65535);
            ASSERT_EQ(field.samples()[k], uint16_t(expected)) << i << "," << j;
        }
    // About pi r^2 / spacing^2 samples.
    EXPECT_NEAR(double(inside), 3.14159 * 15.0 * 15.0, 30.0);
    EXPECT_EQ(rect.i0, craterSamples(field, splat).i0);
    EXPECT_EQ(rect.j1, craterSamples(field, splat).j1);
}

TEST(TerrainCraterSplat, LowersTheCentreAndRaisesTheRim) {
    HeightField field = makeFlat();
    const float ground = field.sampleHeight(0, 0);
    CraterSplat splat = makeSplat();
    splat.center = {256.0f, 256.0f};
    applyCrater(field, splat);
    // Quantisation to 16 bits is 600 / 65535 m, under a centimetre.
    EXPECT_NEAR(field.sampleHeight(64, 64), ground - 14.0f, 0.01f);
    // The rim is at 0.7 * 60 = 42 m, between samples; 44 m (11 samples) is just outside it.
    const float nearRim = tessera::shader::tsCraterOffset(44.0f / 60.0f, 14.0f, 4.0f, 0.7f);
    EXPECT_GT(nearRim, 3.5f);
    EXPECT_NEAR(field.sampleHeight(75, 64), ground + nearRim, 0.01f);
    EXPECT_NEAR(field.sampleHeight(64, 53), ground + nearRim, 0.01f);
    EXPECT_FLOAT_EQ(field.sampleHeight(79, 64), ground); // 60 m: on the radius, untouched
}

TEST(TerrainCraterSplat, DegenerateAndOffFieldSplatsChangeNothing) {
    HeightField field = makeHills();
    const std::vector<uint16_t> before = field.samples();
    CraterSplat splat = makeSplat();
    splat.radius = 0.0f;
    EXPECT_TRUE(applyCrater(field, splat).empty());
    splat.radius = -5.0f;
    EXPECT_TRUE(applyCrater(field, splat).empty());
    splat.radius = 50.0f;
    splat.center = {-100.0f, 200.0f};
    EXPECT_TRUE(applyCrater(field, splat).empty());
    splat.center = {200.0f, 1e9f};
    EXPECT_TRUE(applyCrater(field, splat).empty());
    EXPECT_EQ(field.samples(), before);
}

TEST(TerrainCraterSplat, ClipsAtTheFieldEdgeAndClampsAtZero) {
    HeightField field = makeFlat(100); // under a metre above zero
    CraterSplat splat = makeSplat();
    splat.center = {0.0f, 0.0f};
    const SampleRect rect = applyCrater(field, splat);
    EXPECT_EQ(rect.i0, 0u);
    EXPECT_EQ(rect.j0, 0u);
    EXPECT_EQ(rect.i1, 15u);
    EXPECT_EQ(rect.j1, 15u);
    EXPECT_EQ(field.samples()[0], 0u);
}

TEST(TerrainCraterSplat, TerrainSplatUpdatesEverythingAndQueuesTheSplat) {
    Terrain terrain(makeHills(), 5);
    EXPECT_EQ(terrain.revision(), 0u);
    EXPECT_TRUE(terrain.takePendingSplats().empty());
    const CraterSplat first = makeSplat();
    CraterSplat second = makeSplat();
    second.center = {400.0f, 90.0f};
    second.radius = 35.0f;
    const float before = terrain.heightAt(first.center.x, first.center.y);

    const SampleRect rect = terrain.splat(first);
    EXPECT_FALSE(rect.empty());
    EXPECT_NEAR(terrain.heightAt(first.center.x, first.center.y), before - 14.0f, 0.5f);
    terrain.splat(second);
    EXPECT_EQ(terrain.revision(), 2u);

    // Bounds and detail equal a fresh build from the modified field.
    Terrain fresh(HeightField(terrain.field()), 5);
    const MinMaxPyramid& a = terrain.bounds();
    const MinMaxPyramid& b = fresh.bounds();
    ASSERT_EQ(a.levelCount(), b.levelCount());
    for (uint32_t level = 0; level < a.levelCount(); ++level)
        for (uint32_t z = 0; z < a.levelSize(level); ++z)
            for (uint32_t x = 0; x < a.levelSize(level); ++x) EXPECT_EQ(a.minMax(level, x, z), b.minMax(level, x, z));
    EXPECT_EQ(terrain.detail().edgeError(), fresh.detail().edgeError());
    EXPECT_EQ(terrain.detail().patchError(), fresh.detail().patchError());

    const std::vector<CraterSplat> pending = terrain.takePendingSplats();
    ASSERT_EQ(pending.size(), 2u);
    EXPECT_EQ(pending[0].center, first.center);
    EXPECT_EQ(pending[1].center, second.center);
    EXPECT_EQ(pending[1].radius, second.radius);
    EXPECT_TRUE(terrain.takePendingSplats().empty());
    EXPECT_EQ(terrain.revision(), 2u);
}
