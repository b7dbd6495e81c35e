// core::halveRgba8 and mipLevelCount: the mip levels the characters' maps
// and the terrain's detail textures are uploaded with.
#include "tessera/core/MipChain.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tessera::core {
namespace {

std::vector<uint8_t> solid(uint32_t texels, uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    std::vector<uint8_t> out;
    for (uint32_t i = 0; i < texels; ++i) out.insert(out.end(), {r, g, b, a});
    return out;
}

TEST(MipChain, CountsLevelsDownToOneTexel) {
    EXPECT_EQ(mipLevelCount(1, 1), 1u);
    EXPECT_EQ(mipLevelCount(1024, 1024), 11u);
    EXPECT_EQ(mipLevelCount(512, 64), 10u);
    EXPECT_EQ(mipLevelCount(3, 5), 3u); // 3x5, 1x2, 1x1
}

TEST(MipChain, AveragesColourInLinearLightAndDataAsStored) {
    // Black and white texels side by side: their sRGB mean is mid-grey in
    // light (188), not the bytes' mean (128); a normal map's bytes average
    // as they are; alpha always as it is.
    const std::vector<uint8_t> checker = {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 0};
    const std::vector<uint8_t> colour = halveRgba8(checker, 2, 2, MipEncoding::Srgb);
    ASSERT_EQ(colour.size(), 4u);
    EXPECT_EQ(colour[0], 188);
    EXPECT_EQ(colour[3], 128);
    const std::vector<uint8_t> data = halveRgba8(checker, 2, 2, MipEncoding::Linear);
    EXPECT_EQ(data[0], 128);
    EXPECT_EQ(data[3], 128);
    // A flat image stays what it is at every level, in either encoding.
    std::vector<uint8_t> level = solid(6 * 5, 10, 120, 250, 77);
    uint32_t w = 6, h = 5;
    while (w > 1 || h > 1) {
        level = halveRgba8(level, w, h, MipEncoding::Srgb);
        w = std::max(1u, w / 2), h = std::max(1u, h / 2);
        ASSERT_EQ(level.size(), size_t(w) * h * 4);
        EXPECT_EQ(level, solid(w * h, 10, 120, 250, 77));
    }
}

TEST(MipChain, ASideOfOneAveragesTheOtherAlone) {
    // 4 x 1: pairs along the row; 1 x 2: the column's two texels.
    const std::vector<uint8_t> row = {0, 0, 0, 0, 200, 200, 200, 200, 40, 40, 40, 40, 60, 60, 60, 60};
    const std::vector<uint8_t> halved = halveRgba8(row, 4, 1, MipEncoding::Linear);
    EXPECT_EQ(halved, (std::vector<uint8_t>{100, 100, 100, 100, 50, 50, 50, 50}));
    const std::vector<uint8_t> column = {0, 10, 20, 30, 100, 110, 120, 130};
    EXPECT_EQ(halveRgba8(column, 1, 2, MipEncoding::Linear), (std::vector<uint8_t>{50, 60, 70, 80}));
}

} // namespace
} // namespace tessera::core
