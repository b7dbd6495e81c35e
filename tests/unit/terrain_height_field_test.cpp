// HeightField: bilinear queries, edge clamping, the central-difference normal
// and patch bounds, checked against hand-computed values.

#include "tessera/terrain/HeightField.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using tessera::terrain::HeightField;
using tessera::terrain::TerrainScale;

namespace {

// heightScale 65535 makes one sample unit exactly one metre, so expected
// values can be written as plain sample arithmetic.
constexpr TerrainScale kMetreUnits{2.5f, 65535.0f};

HeightField makeField(uint32_t w, uint32_t h, std::vector<uint16_t> values, TerrainScale scale = kMetreUnits) {
    return HeightField(w, h, std::move(values), scale);
}

// A plane v = 1000 + 3 i + 5 j on a 1 m grid: slopes dh/dx = 3, dh/dz = 5.
HeightField makePlane() {
    const uint32_t w = 9, h = 7;
    std::vector<uint16_t> v(w * h);
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) v[j * w + i] = uint16_t(1000 + 3 * i + 5 * j);
    return makeField(w, h, std::move(v), TerrainScale{1.0f, 65535.0f});
}

void expectVecNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

} // namespace

TEST(TerrainHeightField, ReportsSizeScaleAndWorldExtent) {
    HeightField field = makeField(4, 3, std::vector<uint16_t>(12, 7));
    EXPECT_EQ(field.width(), 4u);
    EXPECT_EQ(field.height(), 3u);
    EXPECT_EQ(field.samples().size(), 12u);
    EXPECT_FLOAT_EQ(field.scale().horizontalSpacing, 2.5f);
    EXPECT_FLOAT_EQ(field.worldSize().x, 7.5f);
    EXPECT_FLOAT_EQ(field.worldSize().y, 5.0f);
}

TEST(TerrainHeightField, SampleHeightConvertsToMetres) {
    HeightField field = makeField(2, 2, {0, 65535, 32768, 1}, TerrainScale{4.0f, 600.0f});
    EXPECT_FLOAT_EQ(field.sampleHeight(0, 0), 0.0f);
    EXPECT_FLOAT_EQ(field.sampleHeight(1, 0), 600.0f);
    EXPECT_NEAR(field.sampleHeight(0, 1), 32768.0f / 65535.0f * 600.0f, 1e-3f);
}

TEST(TerrainHeightField, HeightAtIsExactAtEverySample) {
    const uint32_t w = 5, h = 4;
    std::vector<uint16_t> v(w * h);
    for (uint32_t k = 0; k < v.size(); ++k) v[k] = uint16_t((k * 7919u) % 65536u);
    HeightField field = makeField(w, h, v);
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i)
            EXPECT_EQ(field.heightAt(float(i) * 2.5f, float(j) * 2.5f), field.sampleHeight(i, j))
                << "sample " << i << "," << j;
}

TEST(TerrainHeightField, HeightAtInterpolatesBilinearly) {
    // Cell corners 10 (0,0), 20 (1,0), 30 (0,1), 60 (1,1).
    HeightField field = makeField(2, 2, {10, 20, 30, 60});
    // Halfway along x on the near edge, on the far edge, and in the middle.
    EXPECT_FLOAT_EQ(field.heightAt(1.25f, 0.0f), 15.0f);
    EXPECT_FLOAT_EQ(field.heightAt(1.25f, 2.5f), 45.0f);
    EXPECT_FLOAT_EQ(field.heightAt(1.25f, 1.25f), 30.0f);
    // (0.25, 0.75) in sample units: near = 12.5, far = 37.5 -> 31.25.
    EXPECT_FLOAT_EQ(field.heightAt(0.625f, 1.875f), 31.25f);
}

TEST(TerrainHeightField, HeightAtClampsOutsideTheField) {
    HeightField field = makeField(3, 2, {10, 20, 40, 100, 200, 400});
    EXPECT_FLOAT_EQ(field.heightAt(-50.0f, 0.0f), 10.0f);
    EXPECT_FLOAT_EQ(field.heightAt(-50.0f, -50.0f), 10.0f);
    EXPECT_FLOAT_EQ(field.heightAt(500.0f, -1.0f), 40.0f);
    EXPECT_FLOAT_EQ(field.heightAt(500.0f, 500.0f), 400.0f);
    // Clamped on one axis only: still interpolates along the other.
    EXPECT_FLOAT_EQ(field.heightAt(1.25f, 99.0f), 150.0f);
    EXPECT_FLOAT_EQ(field.heightAt(5.0f, 1.25f), 220.0f);
}

TEST(TerrainHeightField, NormalOfAPlaneIsTheAnalyticNormal) {
    HeightField plane = makePlane();
    const glm::vec3 expected = glm::normalize(glm::vec3(-3.0f, 1.0f, -5.0f));
    // Interior points, on samples and between them.
    for (glm::vec2 p : {glm::vec2(1, 1), glm::vec2(4, 3), glm::vec2(2.3f, 4.6f), glm::vec2(6.9f, 1.1f)})
        expectVecNear(plane.normalAt(p.x, p.y), expected, 1e-4f);
}

TEST(TerrainHeightField, NormalHalvesTheSlopeAcrossAClampedEdge) {
    // Documented edge behaviour, identical to CLAMP_TO_EDGE on the GPU: at x = 0
    // the left tap is clamped, so dh/dx = (h(1) - h(0)) / 2 = 1.5.
    HeightField plane = makePlane();
    expectVecNear(plane.normalAt(0.0f, 3.0f), glm::normalize(glm::vec3(-1.5f, 1.0f, -5.0f)), 1e-4f);
}

TEST(TerrainHeightField, NormalOfFlatGroundPointsUp) {
    HeightField flat = makeField(3, 3, std::vector<uint16_t>(9, 1234));
    expectVecNear(flat.normalAt(2.0f, 2.0f), glm::vec3(0, 1, 0), 0.0f);
}

TEST(TerrainHeightField, SetSampleChangesQueries) {
    HeightField field = makeField(2, 2, {0, 0, 0, 0});
    field.setSample(1, 1, 400);
    EXPECT_EQ(field.samples()[3], 400);
    EXPECT_FLOAT_EQ(field.sampleHeight(1, 1), 400.0f);
    EXPECT_FLOAT_EQ(field.heightAt(1.25f, 1.25f), 100.0f);
}

TEST(TerrainHeightField, MinMaxHeightCoversTheInclusiveRectangle) {
    // 4x3:  5  9  1  7
    //       3 50  2  8
    //       6  4 70  0
    HeightField field = makeField(4, 3, {5, 9, 1, 7, 3, 50, 2, 8, 6, 4, 70, 0});
    auto [lo, hi] = field.minMaxHeight(0, 0, 3, 2);
    EXPECT_FLOAT_EQ(lo, 0.0f);
    EXPECT_FLOAT_EQ(hi, 70.0f);
    std::tie(lo, hi) = field.minMaxHeight(0, 0, 1, 1);
    EXPECT_FLOAT_EQ(lo, 3.0f);
    EXPECT_FLOAT_EQ(hi, 50.0f);
    std::tie(lo, hi) = field.minMaxHeight(2, 0, 3, 1); // excludes the 70 and the 0 below
    EXPECT_FLOAT_EQ(lo, 1.0f);
    EXPECT_FLOAT_EQ(hi, 8.0f);
    std::tie(lo, hi) = field.minMaxHeight(2, 2, 2, 2); // a single sample
    EXPECT_FLOAT_EQ(lo, 70.0f);
    EXPECT_FLOAT_EQ(hi, 70.0f);
}

TEST(TerrainHeightField, MinMaxHeightBoundsInterpolatedHeights) {
    HeightField plane = makePlane();
    auto [lo, hi] = plane.minMaxHeight(2, 1, 5, 4);
    for (float z = 1.0f; z <= 4.0f; z += 0.37f)
        for (float x = 2.0f; x <= 5.0f; x += 0.41f) {
            float y = plane.heightAt(x, z);
            EXPECT_GE(y, lo);
            EXPECT_LE(y, hi);
        }
}
