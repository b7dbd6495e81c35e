// Height-map PNG reading and writing: 16-bit round trips, 8-bit expansion,
// deterministic bytes, and error messages that name the file.
//
// Test inputs in other formats (8-bit, RGB, gray+alpha, bad headers) are made
// by a tiny uncompressed PNG encoder below, so the test needs no image library
// of its own and can build files a real encoder would refuse to write.

#include "tessera/core/Random.h"
#include "tessera/terrain/HeightMapIO.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace tessera::terrain;

namespace {

// --- A minimal PNG encoder: stored (uncompressed) deflate blocks. ---

void putU32(std::vector<uint8_t>& out, uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(v >> shift));
}

uint32_t crc32(const uint8_t* data, size_t size) {
    uint32_t crc = 0xffffffffu;
    for (size_t k = 0; k < size; ++k) {
        crc ^= data[k];
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

void putChunk(std::vector<uint8_t>& out, const char type[5], const std::vector<uint8_t>& data) {
    putU32(out, uint32_t(data.size()));
    std::vector<uint8_t> body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    out.insert(out.end(), body.begin(), body.end());
    putU32(out, crc32(body.data(), body.size()));
}

std::vector<uint8_t> zlibStored(const std::vector<uint8_t>& raw) {
    std::vector<uint8_t> z = {0x78, 0x01};
    size_t pos = 0;
    do {
        size_t n = std::min<size_t>(65535, raw.size() - pos);
        bool last = pos + n == raw.size();
        z.push_back(last ? 1 : 0);
        z.push_back(uint8_t(n));
        z.push_back(uint8_t(n >> 8));
        z.push_back(uint8_t(~n));
        z.push_back(uint8_t(~n >> 8));
        z.insert(z.end(), raw.begin() + long(pos), raw.begin() + long(pos + n));
        pos += n;
    } while (pos < raw.size());
    uint32_t a = 1, b = 0;
    for (uint8_t byte : raw) {
        a = (a + byte) % 65521u;
        b = (b + a) % 65521u;
    }
    putU32(z, (b << 16) | a);
    return z;
}

/// PNG bytes for `w` x `h` pixels of `channels` samples of `depth` bits
/// (colour type chosen from the channel count); `pixels` holds row-major
/// samples, 16-bit ones big-endian as in the file.
std::vector<uint8_t> encodePng(uint32_t w, uint32_t h, int channels, int depth,
                               const std::vector<uint8_t>& pixels) {
    static constexpr uint8_t kColourType[5] = {0, 0, 4, 2, 6};
    std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<uint8_t> ihdr;
    putU32(ihdr, w);
    putU32(ihdr, h);
    ihdr.insert(ihdr.end(), {uint8_t(depth), kColourType[channels], 0, 0, 0});
    putChunk(out, "IHDR", ihdr);
    const size_t rowBytes = size_t(w) * channels * depth / 8;
    std::vector<uint8_t> raw;
    for (uint32_t y = 0; y < h && !pixels.empty(); ++y) {
        raw.push_back(0); // filter: none
        raw.insert(raw.end(), pixels.begin() + long(y * rowBytes), pixels.begin() + long((y + 1) * rowBytes));
    }
    putChunk(out, "IDAT", zlibStored(raw));
    putChunk(out, "IEND", {});
    return out;
}

// --- Fixture: a private scratch folder per test (ctest may run tests in parallel). ---

class TerrainHeightMapIO : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mDir = fs::path(::testing::TempDir()) /
               ("tessera_terrain_io_" + std::string(info->name()) + "_" + std::to_string(getpid()));
        fs::remove_all(mDir);
        fs::create_directories(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }

    fs::path write(const std::string& name, const std::vector<uint8_t>& bytes) {
        fs::path path = mDir / name;
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));
        return path;
    }

    static std::vector<uint8_t> read(const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    void expectError(const fs::path& path, const std::string& fragment) {
        auto result = loadHeightMapPng(path);
        ASSERT_FALSE(result.ok()) << path;
        const std::string& message = result.error().message;
        EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
        EXPECT_NE(message.find(fragment), std::string::npos) << message;
    }

    fs::path mDir;
};

std::vector<uint16_t> randomSamples(size_t count, uint64_t seed) {
    tessera::Random random(seed);
    std::vector<uint16_t> samples(count);
    for (uint16_t& s : samples) s = uint16_t(random.nextU32() >> 16);
    samples[0] = 0; // make sure both extremes survive the trip
    samples[1] = 65535;
    return samples;
}

} // namespace

TEST_F(TerrainHeightMapIO, SixteenBitRoundTripIsLossless) {
    const uint32_t w = 37, h = 23; // odd, non-square
    const std::vector<uint16_t> samples = randomSamples(w * h, 42);
    const fs::path path = mDir / "round_trip.png";
    ASSERT_TRUE(saveHeightMapPng16(path, w, h, samples).ok());

    auto loaded = loadHeightMapPng(path, TerrainScale{2.0f, 100.0f});
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ(loaded->width(), w);
    EXPECT_EQ(loaded->height(), h);
    EXPECT_EQ(loaded->samples(), samples);
    EXPECT_FLOAT_EQ(loaded->scale().horizontalSpacing, 2.0f);
    EXPECT_FLOAT_EQ(loaded->scale().heightScale, 100.0f);
}

TEST_F(TerrainHeightMapIO, SavingTwiceGivesIdenticalBytes) {
    const std::vector<uint16_t> samples = randomSamples(64 * 64, 7);
    ASSERT_TRUE(saveHeightMapPng16(mDir / "a.png", 64, 64, samples).ok());
    ASSERT_TRUE(saveHeightMapPng16(mDir / "b.png", 64, 64, samples).ok());
    EXPECT_EQ(read(mDir / "a.png"), read(mDir / "b.png"));
}

TEST_F(TerrainHeightMapIO, SixteenBitFileFromAnotherEncoderLoads) {
    // Big-endian samples from an independent encoder load unchanged; with the
    // round trip above this also pins our writer's byte order.
    const std::vector<uint16_t> samples = {0x0102, 0xfffe, 0x8000, 0x00ff};
    std::vector<uint8_t> bigEndian;
    for (uint16_t s : samples) bigEndian.insert(bigEndian.end(), {uint8_t(s >> 8), uint8_t(s)});
    auto loaded = loadHeightMapPng(write("gray16.png", encodePng(2, 2, 1, 16, bigEndian)));
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ(loaded->samples(), samples);
}

TEST_F(TerrainHeightMapIO, EightBitValuesExpandToSixteenBits) {
    const std::vector<uint8_t> gray = {0, 1, 128, 255, 0xab, 17};
    auto loaded = loadHeightMapPng(write("gray8.png", encodePng(3, 2, 1, 8, gray)));
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const std::vector<uint16_t> expected = {0, 257, 128 * 257, 65535, 0xabab, 17 * 257};
    EXPECT_EQ(loaded->samples(), expected);
}

TEST_F(TerrainHeightMapIO, GrayAlphaUsesTheGrayChannel) {
    const std::vector<uint8_t> grayAlpha = {10, 255, 20, 0, 30, 128, 40, 7};
    auto loaded = loadHeightMapPng(write("gray_alpha.png", encodePng(2, 2, 2, 8, grayAlpha)));
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const std::vector<uint16_t> expected = {10 * 257, 20 * 257, 30 * 257, 40 * 257};
    EXPECT_EQ(loaded->samples(), expected);
}

TEST_F(TerrainHeightMapIO, MissingFileIsReportedByName) {
    expectError(mDir / "no_such_height_map.png", "not found");
}

TEST_F(TerrainHeightMapIO, TextFileRenamedToPngIsNotAPng) {
    const std::string text = "this is a text file, not an image\n";
    expectError(write("notes.png", std::vector<uint8_t>(text.begin(), text.end())), "not a PNG");
}

TEST_F(TerrainHeightMapIO, ColourPngIsRejected) {
    std::vector<uint8_t> rgb(4 * 4 * 3, 90);
    expectError(write("colour.png", encodePng(4, 4, 3, 8, rgb)),
                "expected a grayscale PNG, got 3 channels");
}

TEST_F(TerrainHeightMapIO, RgbaPngIsRejected) {
    std::vector<uint8_t> rgba(4 * 4 * 4, 90);
    expectError(write("colour_alpha.png", encodePng(4, 4, 4, 8, rgba)), "got 4 channels");
}

TEST_F(TerrainHeightMapIO, CorruptPngIncludesTheDecoderReason) {
    std::vector<uint8_t> bytes = encodePng(8, 8, 1, 8, std::vector<uint8_t>(64, 3));
    bytes.resize(40); // keep the signature and IHDR, cut the image data
    expectError(write("truncated.png", bytes), "corrupt PNG (");
}

TEST_F(TerrainHeightMapIO, TooSmallAndTooLargeAreRejected) {
    expectError(write("one_pixel.png", encodePng(1, 1, 1, 8, {5})), "smaller than the minimum 2x2");
    // Only the header is read before the size check, so no pixels are needed.
    expectError(write("huge.png", encodePng(16385, 2, 1, 8, {})), "larger than the maximum 16384");
}

TEST_F(TerrainHeightMapIO, SaveFailureNamesTheFileAndLeavesNothing) {
    const fs::path path = mDir / "missing_folder" / "out.png";
    auto status = saveHeightMapPng16(path, 2, 2, {1, 2, 3, 4});
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find("out.png"), std::string::npos) << status.error().message;
    EXPECT_FALSE(fs::exists(path));
}

TEST_F(TerrainHeightMapIO, SaveRejectsMismatchedSampleCount) {
    auto status = saveHeightMapPng16(mDir / "short.png", 3, 3, {1, 2, 3});
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find("short.png"), std::string::npos);
}
