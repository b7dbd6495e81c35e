// The terrain's detail textures are content: a broken or misshapen file ends
// the demo with a non-zero status and a message naming the file, instead of a
// run with a flat or garbled terrain. --content DIR is searched first, so a
// bad file there shadows the build's good one.
#include "DemoProcess.h"

#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace tessera;
using namespace tessera::test;

namespace {

class TerrainDetailTextures : public ::testing::Test {
protected:
    void SetUp() override {
        mContent = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) /
                   ("detail_content_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                    "_" + std::to_string(getpid()));
        std::filesystem::remove_all(mContent);
        std::filesystem::create_directories(mContent / "terrain");
    }
    void TearDown() override { std::filesystem::remove_all(mContent); }

    ProcessResult runTerrain() {
        return runDemo({"--scene", "terrain", "--width", "64", "--height", "36", "--frames", "1", "--backend", "r2vb",
                        "--content", mContent.string()});
    }

    std::filesystem::path mContent;
};

} // namespace

TEST_F(TerrainDetailTextures, ABrokenFileIsAnErrorNamingIt) {
    const auto file = mContent / "terrain" / "detail_rock.png";
    std::ofstream(file, std::ios::binary) << "not a PNG";
    const ProcessResult run = runTerrain();
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.exitCode, -1) << "crashed: " << run.output;
    EXPECT_NE(run.output.find(file.string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("detail texture"), std::string::npos) << run.output;
}

TEST_F(TerrainDetailTextures, AMisshapenFileIsAnErrorNamingIt) {
    const auto file = mContent / "terrain" / "detail_snow.png";
    Rgba8Image image{64, 32, std::vector<uint8_t>(64 * 32 * 4, 200)};
    ASSERT_TRUE(writePng(file, image).ok());
    const ProcessResult run = runTerrain();
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.exitCode, -1) << "crashed: " << run.output;
    EXPECT_NE(run.output.find(file.string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("64x32"), std::string::npos) << run.output;
}
