// The transform-feedback capture of the device's fixed-function tessellator:
// known patterns come back exactly, so comparisons with the emulated
// tessellator can trust it.
#include "TessellationCaptureFixture.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

using namespace tessera;
using namespace tessera::test;

namespace {

std::set<std::tuple<float, float, float>> uniquePoints(const TessellationCaptureResult& r) {
    std::set<std::tuple<float, float, float>> points;
    for (const auto& v : r.vertices) points.emplace(v.x, v.y, v.z);
    return points;
}

using TessellationCaptureTest = TessellationCaptureFixture;

// A triangle tessellated uniformly at integer level n is a set of concentric
// rings with n, n-2, ... segments per side (down to a centre point or one
// triangle); between rings of m and m-2 segments lie 6(m-1) triangles.
uint32_t ringTriangles(uint32_t n) {
    uint32_t triangles = 0;
    for (uint32_t m = n; m >= 2; m -= 2) triangles += 6 * (m - 1);
    return triangles + (n % 2 == 1 ? 1 : 0);
}

uint32_t ringPoints(uint32_t n) {
    uint32_t points = 0;
    for (uint32_t m = n; m >= 1; m -= 2) {
        points += 3 * m;
        if (m < 2) break;
    }
    return points + (n % 2 == 0 ? 1 : 0);
}

} // namespace

TEST_F(TessellationCaptureTest, UniformIntegerQuadIsAGrid) {
    for (float level : {1.0f, 2.0f, 5.0f, 16.0f}) {
        auto r = capture->run(CaptureDomain::Quad, CaptureSpacing::Equal, {level, level, level, level}, {level, level});
        ASSERT_TRUE(r.ok()) << r.error().message;
        const uint32_t n = uint32_t(level);
        EXPECT_EQ(r.value().primitivesWritten, 2u * n * n) << level;
        EXPECT_EQ(r.value().vertices.size(), 6u * n * n) << level;
        EXPECT_EQ(uniquePoints(r.value()).size(), size_t(n + 1) * (n + 1)) << level;
        for (const auto& v : r.value().vertices) {
            EXPECT_GE(v.x, 0.0f);
            EXPECT_LE(v.x, 1.0f);
        }
    }
}

TEST_F(TessellationCaptureTest, UniformIntegerTriangleIsConcentricRings) {
    for (float level : {1.0f, 2.0f, 3.0f, 8.0f}) {
        auto r = capture->run(CaptureDomain::Triangle, CaptureSpacing::Equal, {level, level, level, 0.0f}, {level, 0.0f});
        ASSERT_TRUE(r.ok()) << r.error().message;
        const uint32_t n = uint32_t(level);
        EXPECT_EQ(r.value().primitivesWritten, ringTriangles(n)) << level;
        EXPECT_EQ(uniquePoints(r.value()).size(), ringPoints(n)) << level;
        for (const auto& v : r.value().vertices) EXPECT_NEAR(v.x + v.y + v.z, 1.0f, 1e-6f);
    }
}

TEST_F(TessellationCaptureTest, ZeroOuterLevelCullsThePatch) {
    auto r = capture->run(CaptureDomain::Quad, CaptureSpacing::FractionalOdd, {0.0f, 4.0f, 4.0f, 4.0f}, {4.0f, 4.0f});
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r.value().primitivesWritten, 0u);
}
