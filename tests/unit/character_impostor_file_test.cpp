// The .impostor file (ImpostorFile.h): an atlas survives a write and a read
// byte for byte, and a truncated, corrupted, foreign, wrong-version or
// wrong-layout file is refused with one line naming the file and the
// problem, never a crash.
#include "tessera/character/ImpostorFile.h"
#include "tessera/shaders/CrowdImpostor.h"

#include "SyntheticImpostorAtlas.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <limits>
#include <string>

using namespace tessera;
using namespace tessera::character;

namespace {

void expectSame(const ImpostorAtlas& a, const ImpostorAtlas& b) {
    EXPECT_EQ(a.size, b.size);
    EXPECT_EQ(a.layers, b.layers);
    EXPECT_EQ(a.centreY, b.centreY);
    EXPECT_EQ(a.radius, b.radius);
    EXPECT_TRUE(a.albedo == b.albedo);
    EXPECT_TRUE(a.normal == b.normal);
}

void writeBytes(const std::filesystem::path& file, const std::vector<uint8_t>& bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

void put32(std::vector<uint8_t>& bytes, size_t offset, uint32_t value) {
    std::memcpy(bytes.data() + offset, &value, 4);
}

// `bytes` written to a file and read back must fail with every piece of `text`.
void expectRefused(const std::vector<uint8_t>& bytes, const std::string& name,
                   std::initializer_list<const char*> text) {
    const std::filesystem::path file = test::testOutputDir("impostor_file") / (name + ".impostor");
    writeBytes(file, bytes);
    const auto read = readImpostorFile(file);
    ASSERT_FALSE(read) << name << ": accepted";
    const std::string& message = read.error().message;
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    for (const char* piece : text) EXPECT_NE(message.find(piece), std::string::npos) << name << ": " << message;
}

} // namespace

TEST(ImpostorFile, RoundTripsAnAtlasByteForByte) {
    const ImpostorAtlas atlas = test::syntheticImpostorAtlas(0, 2);
    const std::filesystem::path file = test::testOutputDir("impostor_file") / "round_trip.impostor";
    ASSERT_TRUE(writeImpostorFile(file, atlas));
    EXPECT_EQ(std::filesystem::file_size(file), atlas.bytes() + 56);
    const auto read = readImpostorFile(file);
    ASSERT_TRUE(read) << read.error().message;
    expectSame(read.value(), atlas);
    EXPECT_TRUE(encodeImpostorAtlas(read.value()) == encodeImpostorAtlas(atlas));
}

TEST(ImpostorFile, RefusesTruncatedCorruptAndForeignFiles) {
    const std::vector<uint8_t> good = encodeImpostorAtlas(test::syntheticImpostorAtlas(0, 1));
    expectRefused({}, "empty", {"truncated: 0 bytes"});
    expectRefused({good.begin(), good.begin() + 5}, "five_bytes", {"truncated: 5 bytes"});
    expectRefused({good.begin(), good.begin() + 30}, "part_header", {"truncated: 30 bytes, the header alone takes 56"});
    expectRefused({good.begin(), good.begin() + 1000}, "part_images", {"truncated: 1000 bytes, its 8 layers need"});
    expectRefused({good.begin(), good.end() - 1}, "one_short", {"truncated"});
    std::vector<uint8_t> longer = good;
    longer.push_back(0);
    expectRefused(longer, "trailing", {"1 bytes after the end of its 8 layers"});
    std::vector<uint8_t> flipped = good;
    flipped[good.size() / 2] ^= 0x10;
    expectRefused(flipped, "corrupt", {"checksum mismatch"});
    expectRefused({'P', 'K', 3, 4, 0, 0, 0, 0, 0, 0}, "foreign", {"not a Tessera impostor file"});
}

TEST(ImpostorFile, RefusesAnotherVersionOrLayout) {
    const std::vector<uint8_t> good = encodeImpostorAtlas(test::syntheticImpostorAtlas(0, 1));
    std::vector<uint8_t> bytes = good;
    put32(bytes, 8, kImpostorFileVersion + 1);
    expectRefused(bytes, "version", {"version 2, this build reads version 1"});
    bytes = good;
    put32(bytes, 12, 2 * TS_IMPOSTOR_VIEWS);
    expectRefused(bytes, "views", {"baked with views 16, this build draws 8"});
    bytes = good;
    put32(bytes, 24, TS_IMPOSTOR_MIPS + 1);
    expectRefused(bytes, "mips", {"baked with mips 5"});
    bytes = good;
    put32(bytes, 32, 128);
    expectRefused(bytes, "size", {"layers of 128 texels a side"});
    bytes = good;
    put32(bytes, 36, TS_IMPOSTOR_PHASES + 3);
    expectRefused(bytes, "layers", {"11 layers, not a whole number of clips"});
    bytes = good;
    put32(bytes, 36, 0xfffffff8u);
    expectRefused(bytes, "huge", {"truncated", "its 4294967288 layers need"});
    bytes = good;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bytes.data() + 44, &nan, 4);
    expectRefused(bytes, "radius", {"bad sphere"});
    bytes = good;
    put32(bytes, 36, 2 * TS_IMPOSTOR_PHASES);
    expectRefused(bytes, "more_layers", {"truncated", "its 16 layers need"});
}

TEST(ImpostorFile, NamesAMissingOrUnwritableFile) {
    const std::filesystem::path missing = test::testOutputDir("impostor_file") / "missing.impostor";
    std::filesystem::remove(missing);
    const auto read = readImpostorFile(missing);
    ASSERT_FALSE(read);
    EXPECT_EQ(read.error().message, missing.string() + ": cannot open the impostor file");
    const std::filesystem::path nowhere = test::testOutputDir("impostor_file") / "no_such_dir" / "x.impostor";
    const Status written = writeImpostorFile(nowhere, test::syntheticImpostorAtlas(0, 1));
    ASSERT_FALSE(written);
    EXPECT_EQ(written.error().message, nowhere.string() + ": cannot write the impostor file");
}
