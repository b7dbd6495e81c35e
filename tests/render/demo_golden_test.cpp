// Renders a fixed view headless on every backend under the validation layer
// and compares it with the approved golden image (tests/golden/goldens.txt
// names each backend's file, shared where backends render the same image;
// approve new ones with tools/approve_goldens.sh).
#include "DemoProcess.h"
#include "ImageCompare.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace tessera;
using namespace tessera::test;

namespace {

const std::string kOut = TESSERA_TEST_OUTPUT_DIR;
// A view across a valley towards the mountains, far enough out that every
// tile is in play and near enough that the shading detail shows.
const std::vector<std::string> kFixedView = {"--scene", "terrain", "--width", "320", "--height", "180", "--frames", "3", "--camera",
                                             "1800,900,6800,-30,-16"};

class GoldenImage : public ::testing::TestWithParam<std::string> {};

/// The golden file `backend` is compared with, from tests/golden/goldens.txt
/// ("BACKEND FILE" lines, '#' comments); empty when it names none.
std::string goldenFileFor(const std::string& backend) {
    std::ifstream manifest(std::string(TESSERA_GOLDEN_DIR) + "/goldens.txt");
    std::string line;
    while (std::getline(manifest, line)) {
        std::istringstream fields(line);
        std::string name, file;
        if (fields >> name >> file && name[0] != '#' && name == backend) return file;
    }
    return {};
}

} // namespace

TEST_P(GoldenImage, MatchesApprovedImageWithNoValidationMessages) {
    const std::string backend = GetParam();
    const std::string shot = kOut + "/golden_" + backend + ".png";
    std::filesystem::remove(shot);
    auto args = kFixedView;
    args.insert(args.end(), {"--backend", backend, "--validation", "--screenshot", shot});
    auto run = runDemo(args);
    if (deviceCannotRun(run)) GTEST_SKIP() << backend << ": the device cannot run it\n" << run.output;
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;

    auto actual = readPng(shot);
    ASSERT_TRUE(actual.ok()) << actual.error().message;
    const std::string goldenFile = goldenFileFor(backend);
    ASSERT_FALSE(goldenFile.empty()) << "tests/golden/goldens.txt names no golden image for " << backend;
    const std::string goldenPath = std::string(TESSERA_GOLDEN_DIR) + "/" + goldenFile;
    auto golden = readPng(goldenPath);
    ASSERT_TRUE(golden.ok()) << "no golden image for " << backend << " (" << golden.error().message
                             << "); approve " << shot << " with tools/approve_goldens.sh";
    auto cmp = compareImages(actual.value(), golden.value(), {}, kOut + "/golden_" + backend + ".diff.png");
    EXPECT_TRUE(cmp.match) << backend << ": " << cmp.message;
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, GoldenImage, ::testing::Values("r2vb", "streamout", "hulldomain", "meshshader"),
                         [](const auto& test) { return test.param; });

TEST(DemoRun, FlythroughIsDeterministicForASeed) {
    auto shot = [&](const std::string& name) {
        const std::string path = kOut + "/" + name;
        auto run = runDemo({"--scene", "terrain", "--width", "160", "--height", "90", "--frames", "4", "--seed", "7", "--backend", "r2vb",
                            "--screenshot", path});
        EXPECT_EQ(run.exitCode, 0) << run.output;
        return readPng(path);
    };
    auto a = shot("seed7_a.png");
    auto b = shot("seed7_b.png");
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->pixels, b->pixels);
}

TEST(DemoRun, AnyValidationMessageFailsTheRun) {
    auto run = runDemo({"--scene", "terrain", "--plugin-dir", TESSERA_TEST_PLUGIN_DIR "/demo", "--backend", "invalid-usage", "--frames", "2",
                        "--width", "64", "--height", "64", "--validation"});
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("VUID-vkCmdSetViewport"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("validation messages: 0"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("validation messages: "), std::string::npos) << run.output;
}

TEST(DemoRun, NullBackendRunsFramesWithoutAGpu) {
    auto run = runDemo({"--scene", "terrain", "--backend", "null", "--frames", "5", "--validation"});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    // The null backend creates no Vulkan instance, so there is nothing to validate.
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;
}
