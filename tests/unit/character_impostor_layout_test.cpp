// The impostor tier's view layout (CrowdImpostor.h), shared by the baker and
// every backend's draw: the hemi-octahedral map round-trips, every cell's
// direction falls in that cell, the cell's square maps inside its border,
// projection frames the sphere, and phases pair as the clips do.
#include "tessera/shaders/CrowdImpostor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace tessera;
using namespace tessera::shader;

TEST(ImpostorLayout, EncodeDecodeRoundTripsOverTheUpperHemisphere) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < 2000; ++i) {
        glm::vec3 d(unit(random), std::abs(unit(random)), unit(random));
        if (glm::length(d) < 1e-3f) continue;
        d = glm::normalize(d);
        const glm::vec2 uv = tsImpostorEncode(d);
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LE(uv.x, 1.0f);
        ASSERT_GE(uv.y, 0.0f);
        ASSERT_LE(uv.y, 1.0f);
        const glm::vec3 back = tsImpostorDecode(uv);
        ASSERT_LT(glm::length(back - d), 1e-5f) << d.x << " " << d.y << " " << d.z;
    }
    // Below the horizon counts as at the horizon; any length will do.
    EXPECT_LT(glm::length(tsImpostorDecode(tsImpostorEncode({3.0f, -2.0f, 0.0f})) - glm::vec3(1.0f, 0.0f, 0.0f)),
              1e-6f);
    EXPECT_LT(glm::length(tsImpostorDecode(tsImpostorEncode({0.0f, 5.0f, 0.0f})) - glm::vec3(0.0f, 1.0f, 0.0f)), 1e-6f);
}

TEST(ImpostorLayout, EveryCellsDirectionIsAnUpperUnitVectorInThatCell) {
    for (uint32_t row = 0; row < TS_IMPOSTOR_VIEWS; ++row) {
        for (uint32_t column = 0; column < TS_IMPOSTOR_VIEWS; ++column) {
            const glm::uvec2 cell(column, row);
            const glm::vec3 d = tsImpostorCellDirection(cell);
            EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
            EXPECT_GE(d.y, 0.0f);
            EXPECT_EQ(tsImpostorCell(d), cell) << column << ", " << row;
        }
    }
    // Straight ahead (+Z) is the top-right corner, straight above the centre.
    EXPECT_EQ(tsImpostorCell({0.0f, 0.0f, 1.0f}), glm::uvec2(TS_IMPOSTOR_VIEWS - 1, 0));
    EXPECT_EQ(tsImpostorCell({0.0f, 0.0f, -1.0f}), glm::uvec2(0, TS_IMPOSTOR_VIEWS - 1));
    EXPECT_GT(tsImpostorCellDirection(glm::uvec2(TS_IMPOSTOR_VIEWS / 2)).y, 0.9f);
}

TEST(ImpostorLayout, TheSquareSpansTheCellsInnerTexelsAtEveryMip) {
    const float border = float(TS_IMPOSTOR_BORDER), cell = float(TS_IMPOSTOR_CELL);
    EXPECT_EQ(tsImpostorCellTexel({0.0f, 0.0f}), glm::vec2(border));
    EXPECT_EQ(tsImpostorCellTexel({1.0f, 1.0f}), glm::vec2(cell - border));
    const float layer = float(TS_IMPOSTOR_VIEWS) * cell;
    const glm::uvec2 c(3, 5);
    EXPECT_EQ(tsImpostorLayerUv(c, {0.0f, 0.0f}) * layer, glm::vec2(3.0f, 5.0f) * cell + border);
    EXPECT_EQ(tsImpostorLayerUv(c, {1.0f, 1.0f}) * layer, glm::vec2(4.0f, 6.0f) * cell - border);
    // Coordinates of the whole layer: the same uv is the same point at mip m.
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        const float texels = layer / float(1u << m);
        const glm::vec2 corner = tsImpostorLayerUv(c, {0.0f, 0.0f}) * texels;
        EXPECT_GE(corner.x, 3.0f * cell / float(1u << m));
        EXPECT_LE(tsImpostorLayerUv(c, {1.0f, 1.0f}).x * texels, 4.0f * cell / float(1u << m));
    }
}

TEST(ImpostorLayout, ProjectionFramesTheSphere) {
    const glm::vec3 centre(0.0f, 0.8f, 0.0f);
    const float radius = 1.5f;
    for (uint32_t i = 0; i < TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_VIEWS; ++i) {
        const glm::vec3 d = tsImpostorCellDirection(glm::uvec2(i % TS_IMPOSTOR_VIEWS, i / TS_IMPOSTOR_VIEWS));
        glm::vec3 right, up;
        tsImpostorAxes(d, right, up);
        EXPECT_LT(glm::length(tsImpostorProject(centre, d, centre, radius) - glm::vec3(0.5f, 0.5f, 0.0f)), 1e-6f);
        EXPECT_LT(
            glm::length(tsImpostorProject(centre + radius * right, d, centre, radius) - glm::vec3(1.0f, 0.5f, 0.0f)),
            1e-5f);
        EXPECT_LT(glm::length(tsImpostorProject(centre + radius * up, d, centre, radius) - glm::vec3(0.5f, 0.0f, 0.0f)),
                  1e-5f);
        EXPECT_NEAR(tsImpostorProject(centre + d, d, centre, radius).z, 1.0f, 1e-5f);
    }
}

TEST(ImpostorLayout, PhasesPairAsTheClipsLoopOrClamp) {
    uint32_t a = 0, b = 0;
    EXPECT_NEAR(tsImpostorPhasePair(7.5f / 8.0f, true, 16, a, b), 0.5f, 1e-6f);
    EXPECT_EQ(a, 23u);
    EXPECT_EQ(b, 16u); // a loop wraps to its first phase
    EXPECT_NEAR(tsImpostorPhasePair(1.5f, false, 0, a, b), 0.0f, 1e-6f);
    EXPECT_EQ(a, 7u);
    EXPECT_EQ(b, 7u); // a clamped clip ends on its last
    EXPECT_NEAR(tsImpostorPhasePair(2.5f / 7.0f, false, 0, a, b), 0.5f, 1e-5f);
    EXPECT_EQ(a, 2u);
    EXPECT_EQ(b, 3u);
}
