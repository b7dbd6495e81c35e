// character::bakeImpostors on a small synthetic character (the exporter
// tests' skinned tube, a base colour red on one half of its u range and blue
// on the other): the same bytes for any thread count, a layer per clip and
// phase framed by the crowd's sphere, the silhouette in every cell and never
// in a border, the colour each side shows, dilation and mips.
#include "tessera/character/AnimatedBounds.h"
#include "tessera/character/ImpostorBaker.h"
#include "tessera/shaders/CrowdImpostor.h"

#include "../content/GlbTestCharacter.h"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

using namespace tessera;
using namespace tessera::character;

namespace {

constexpr uint32_t kCell = TS_IMPOSTOR_CELL;

// The tube (8 segments, 4 rings, up +Y from 0 to 2) with one clip, "bend"
// (the spine bends 0.5 rad about +Z and back over 1 s), and a 2 x 1 map:
// u < 0.5 red, else blue. Its front (+Z, angle pi / 2) has u = 0.25 (red),
// its back u = 0.75 (blue).
CharacterAsset makeTube() {
    CharacterAsset tube = test::makeTestCharacter(8, 4);
    tube.clips.resize(1);
    TextureImage map;
    map.width = 2;
    map.height = 1;
    map.bytes = {255, 0, 0, 255, 0, 0, 255, 255};
    tube.baseColor = map;
    return tube;
}

class ImpostorBaker : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        tube = new CharacterAsset(makeTube());
        const auto start = std::chrono::steady_clock::now();
        atlas = new ImpostorAtlas(bakeImpostors(*tube, {{}, 1}));
        std::cout << "tube (" << tube->cage.triangleCount() << " triangles, " << atlas->layers << " layers): "
                  << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()
                  << " ms on one thread\n";
    }
    static void TearDownTestSuite() {
        delete atlas;
        delete tube;
    }

    static const uint8_t* texel(const std::vector<uint8_t>& image, uint32_t mip, uint32_t layer, uint32_t x,
                                uint32_t y) {
        const size_t side = size_t(atlas->sizeAt(mip));
        return image.data() + size_t(atlas->layerBytes(mip)) * layer + (y * side + x) * 4;
    }
    // Alpha summed over cell `cell`'s texels at `mip`, and over its border ring.
    static void cellCoverage(uint32_t mip, uint32_t layer, glm::uvec2 cell, uint32_t& inside, uint32_t& border) {
        const uint32_t side = kCell >> mip;
        inside = border = 0;
        for (uint32_t y = 0; y < side; ++y) {
            for (uint32_t x = 0; x < side; ++x) {
                const uint8_t a = texel(atlas->albedo[mip], mip, layer, cell.x * side + x, cell.y * side + y)[3];
                const bool edge = x < TS_IMPOSTOR_BORDER || y < TS_IMPOSTOR_BORDER || x >= side - TS_IMPOSTOR_BORDER ||
                                  y >= side - TS_IMPOSTOR_BORDER;
                (edge ? border : inside) += a;
            }
        }
    }

    static inline CharacterAsset* tube = nullptr;
    static inline ImpostorAtlas* atlas = nullptr;
};

} // namespace

TEST_F(ImpostorBaker, HasALayerPerClipAndPhaseFramedByTheCrowdsSphere) {
    EXPECT_EQ(atlas->size, TS_IMPOSTOR_VIEWS * kCell);
    EXPECT_EQ(atlas->layers, TS_IMPOSTOR_PHASES);
    EXPECT_EQ(impostorLayerCount(3), 3 * TS_IMPOSTOR_PHASES);
    EXPECT_EQ(impostorLayerCount(0), TS_IMPOSTOR_PHASES);
    ASSERT_EQ(atlas->albedo.size(), TS_IMPOSTOR_MIPS);
    ASSERT_EQ(atlas->normal.size(), TS_IMPOSTOR_MIPS);
    uint64_t bytes = 0;
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        EXPECT_EQ(atlas->albedo[m].size(),
                  uint64_t(kCell * TS_IMPOSTOR_VIEWS >> m) * (kCell * TS_IMPOSTOR_VIEWS >> m) * 4 * atlas->layers);
        EXPECT_EQ(atlas->normal[m].size(), atlas->albedo[m].size());
        bytes += 2 * atlas->albedo[m].size();
    }
    EXPECT_EQ(atlas->bytes(), bytes);
    // The instance sphere of runtime/src/crowd/SimulatedCrowd.cpp, exactly.
    const scene::Aabb box = animatedBounds(*tube);
    EXPECT_EQ(atlas->centreY, box.center().y);
    EXPECT_EQ(atlas->radius, glm::length(box.extents()) + glm::length(glm::vec2(box.center().x, box.center().z)));
}

TEST_F(ImpostorBaker, BakesTheSameBytesOnEveryRunAndThreadCount) {
    for (uint32_t threads : {1u, 2u, 0u}) {
        SCOPED_TRACE(threads);
        const ImpostorAtlas again = bakeImpostors(*tube, {{}, threads});
        EXPECT_EQ(again.centreY, atlas->centreY);
        EXPECT_EQ(again.radius, atlas->radius);
        EXPECT_TRUE(again.albedo == atlas->albedo);
        EXPECT_TRUE(again.normal == atlas->normal);
    }
}

TEST_F(ImpostorBaker, SilhouetteIsInEveryCellAtEveryMipAndNeverInTheBorder) {
    for (uint32_t layer = 0; layer < atlas->layers; ++layer) {
        for (uint32_t row = 0; row < TS_IMPOSTOR_VIEWS; ++row) {
            for (uint32_t column = 0; column < TS_IMPOSTOR_VIEWS; ++column) {
                uint32_t inside = 0, border = 0;
                cellCoverage(0, layer, {column, row}, inside, border);
                EXPECT_GT(inside, 0u) << "layer " << layer << " cell " << column << ", " << row;
                EXPECT_EQ(border, 0u) << "layer " << layer << " cell " << column << ", " << row;
                for (uint32_t m = 1; m < TS_IMPOSTOR_MIPS; ++m) {
                    cellCoverage(m, layer, {column, row}, inside, border);
                    EXPECT_GT(inside + border, 0u) << "mip " << m << " cell " << column << ", " << row;
                }
            }
        }
    }
}

TEST_F(ImpostorBaker, FrontAndBackCellsShowTheirSidesOfTheBaseColour) {
    // Straight ahead (+Z) is the top-right cell, behind (-Z) the bottom-left;
    // the texel at the cell's centre sees the tube's axis at mid height.
    const uint32_t last = TS_IMPOSTOR_VIEWS - 1, mid = kCell / 2;
    const uint8_t* front = texel(atlas->albedo[0], 0, 0, last * kCell + mid, mid);
    const uint8_t* back = texel(atlas->albedo[0], 0, 0, mid, last * kCell + mid);
    EXPECT_EQ(front[3], 255);
    EXPECT_GT(front[0], 200);
    EXPECT_LT(front[2], 55);
    EXPECT_EQ(back[3], 255);
    EXPECT_LT(back[0], 55);
    EXPECT_GT(back[2], 200);
    // The normal there faces the viewer: +Z in front, -Z behind.
    const uint8_t* frontNormal = texel(atlas->normal[0], 0, 0, last * kCell + mid, mid);
    const uint8_t* backNormal = texel(atlas->normal[0], 0, 0, mid, last * kCell + mid);
    EXPECT_GT(frontNormal[2], 230);
    EXPECT_LT(backNormal[2], 25);
    EXPECT_EQ(frontNormal[3], 255);
}

TEST_F(ImpostorBaker, UncoveredTexelsTakeTheCreaturesColourAtEveryMip) {
    // Red or blue or a blend of them everywhere, never black or the grey of
    // an empty cell: dilation, then each cell's mean, then the mips.
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        const std::vector<uint8_t>& image = atlas->albedo[m];
        for (size_t i = 0; i < image.size(); i += 4) {
            ASSERT_GT(image[i] + image[i + 2], 200) << "mip " << m << " byte " << i;
            ASSERT_LT(image[i + 1], 10) << "mip " << m << " byte " << i;
        }
    }
}

TEST_F(ImpostorBaker, MipsAverageTheCoverageOfTheLevelAbove) {
    for (uint32_t m = 1; m < TS_IMPOSTOR_MIPS; ++m) {
        const uint32_t side = atlas->sizeAt(m);
        for (uint32_t y = 0; y < side; ++y) {
            for (uint32_t x = 0; x < side; ++x) {
                int sum = 0;
                for (uint32_t k = 0; k < 4; ++k)
                    sum += texel(atlas->albedo[m - 1], m - 1, 3, 2 * x + k % 2, 2 * y + k / 2)[3];
                // Each level is rounded from the float level above, not from
                // its bytes: within one step per level.
                ASSERT_NEAR(texel(atlas->albedo[m], m, 3, x, y)[3], sum / 4.0, 1.0 * m) << m << ": " << x << ", " << y;
            }
        }
    }
}

TEST_F(ImpostorBaker, PhasesFollowTheClip) {
    // Phase 4 of 8 is the bend's widest (0.5 rad at half its second).
    EXPECT_FALSE(std::equal(atlas->albedo[0].begin(), atlas->albedo[0].begin() + atlas->layerBytes(0),
                            atlas->albedo[0].begin() + 4 * atlas->layerBytes(0)));
}

TEST_F(ImpostorBaker, ACharacterWithoutClipsHasItsRestPoseAtEveryPhase) {
    CharacterAsset still = *tube;
    still.clips.clear();
    still.baseColor.reset();
    const ImpostorAtlas rest = bakeImpostors(still);
    ASSERT_EQ(rest.layers, TS_IMPOSTOR_PHASES);
    const size_t layer = size_t(rest.layerBytes(0));
    for (uint32_t k = 1; k < rest.layers; ++k)
        EXPECT_TRUE(
            std::equal(rest.albedo[0].begin(), rest.albedo[0].begin() + layer, rest.albedo[0].begin() + k * layer));
    // Without a map: the grey the meshes draw without one.
    const uint32_t mid = kCell / 2;
    const uint8_t* centre = rest.albedo[0].data() + (mid * size_t(rest.size) + mid) * 4;
    EXPECT_EQ(centre[0], 150);
    EXPECT_EQ(centre[1], 150);
    EXPECT_EQ(centre[3], 255);
    EXPECT_TRUE(bakeImpostors(CharacterAsset{}).empty());
}
