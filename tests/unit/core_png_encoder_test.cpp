// The one PNG encoder (tessera/core/ImageFile.h): every layout comes back
// exactly through the one decoder, equal pixels give equal bytes, and bad
// input is a checked error.

#include "tessera/core/ImageFile.h"
#include "tessera/core/Random.h"
#include "tessera/terrain/HeightMapIO.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace fs = std::filesystem;
using namespace tessera;

namespace {

fs::path outputDir() {
    fs::path dir = fs::temp_directory_path() / "tessera_core_png_encoder_test";
    fs::create_directories(dir);
    return dir;
}

std::vector<uint16_t> randomSamples(size_t count, uint64_t seed) {
    Random random(seed);
    std::vector<uint16_t> samples(count);
    for (uint16_t& s : samples) s = uint16_t(random.nextU32());
    return samples;
}

} // namespace

TEST(CorePngEncoder, Rgba8RoundTrips) {
    Rgba8Image image{5, 3, std::vector<uint8_t>(5 * 3 * 4)};
    Random random(3);
    for (uint8_t& byte : image.pixels) byte = uint8_t(random.nextU32());
    const fs::path path = outputDir() / "nested" / "rgba.png"; // the RGBA form creates folders
    ASSERT_TRUE(writePng(path, image).ok());
    auto back = readPng(path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->width, 5u);
    EXPECT_EQ(back->height, 3u);
    EXPECT_EQ(back->pixels, image.pixels);
}

TEST(CorePngEncoder, GrayLayoutsRoundTrip) {
    const std::vector<uint16_t> wide = randomSamples(7 * 4, 11);
    const fs::path path16 = outputDir() / "gray16.png";
    ASSERT_TRUE(writePng(path16, PngPixels{7, 4, PngLayout::Gray16, wide.data()}).ok());
    auto loaded16 = terrain::loadHeightMapPng(path16);
    ASSERT_TRUE(loaded16.ok()) << loaded16.error().message;
    EXPECT_EQ(loaded16->samples(), wide);

    const std::vector<uint8_t> narrow = {0, 1, 127, 128, 200, 255};
    const fs::path path8 = outputDir() / "gray8.png";
    ASSERT_TRUE(writePng(path8, PngPixels{3, 2, PngLayout::Gray8, narrow.data()}).ok());
    auto loaded8 = terrain::loadHeightMapPng(path8);
    ASSERT_TRUE(loaded8.ok()) << loaded8.error().message;
    for (size_t k = 0; k < narrow.size(); ++k) EXPECT_EQ(loaded8->samples()[k], narrow[k] * 257u);
}

TEST(CorePngEncoder, EqualPixelsGiveEqualBytes) {
    const std::vector<uint16_t> samples = randomSamples(64 * 64, 5);
    const PngPixels pixels{64, 64, PngLayout::Gray16, samples.data()};
    auto a = encodePng(pixels);
    auto b = encodePng(pixels);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(*a, *b);
    EXPECT_EQ(std::vector<uint8_t>(a->begin(), a->begin() + 4), (std::vector<uint8_t>{0x89, 'P', 'N', 'G'}));
}

TEST(CorePngEncoder, BadInputIsAnError) {
    const uint8_t pixel[4] = {};
    EXPECT_FALSE(encodePng(PngPixels{0, 1, PngLayout::Rgba8, pixel}).ok());
    EXPECT_FALSE(encodePng(PngPixels{1, 1, PngLayout::Rgba8, nullptr}).ok());
    const fs::path path = outputDir() / "no_such_folder" / "x.png";
    Status status = writePng(path, PngPixels{1, 1, PngLayout::Rgba8, pixel});
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find("x.png"), std::string::npos) << status.error().message;
    EXPECT_FALSE(fs::exists(path));
}
