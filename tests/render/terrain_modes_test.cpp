// The first paper's Table 2 modes from one fixed view: the low-resolution
// control mesh draws the fewest triangles, adaptive tessellation more, and
// continuous tessellation at level 32 by far the most (triangle counts from
// the pipeline statistics in --benchmark). Backends that draw only the
// low-resolution mode refuse the others clearly, and level limits are checked.
#include "DemoProcess.h"
#include "JsonFile.h"
#include "TestFiles.h"

#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

using namespace tessera::test;

namespace {

const char* const kCamera = "1800,900,6800,-30,-16";

std::string joined(const std::vector<std::string>& args) {
    std::string text = "tessera-demo";
    for (const auto& a : args) {
        text += ' ';
        text += shellQuote(a);
    }
    return text;
}

/// gpuFrame.statsMedianFrame.clippingInvocations of the --benchmark report at `path`.
std::optional<double> gpuFrameTriangles(const std::string& path) {
    nlohmann::json report;
    std::string error;
    if (!readJsonFile(path, report, error)) return std::nullopt;
    const nlohmann::json* frame = memberOf(report, "gpuFrame");
    const nlohmann::json* stats = frame ? memberOf(*frame, "statsMedianFrame") : nullptr;
    return stats ? numberAt(*stats, "clippingInvocations") : std::nullopt;
}

struct ModeRun {
    std::string command;
    ProcessResult result;
    std::optional<double> triangles; ///< gpuFrame.statsMedianFrame.clippingInvocations
    std::string screenshot;
};

/// One benchmark run of `mode` from the fixed view, with a screenshot.
ModeRun runMode(const std::string& name, const std::vector<std::string>& extra) {
    const auto dir = testOutputDir("terrain_modes");
    const std::string bench = (dir / (name + ".json")).string();
    ModeRun run;
    run.screenshot = (dir / (name + ".png")).string();
    std::filesystem::remove(bench);
    std::filesystem::remove(run.screenshot);
    std::vector<std::string> args = {
        "--scene", "terrain", "--backend", "hulldomain",  "--validation", "--camera",     kCamera,       "--width",
        "320",       "--height",    "180",          "--frames",     "3",           "--warmup",
        "1",         "--benchmark", bench,          "--screenshot", run.screenshot};
    args.insert(args.end(), extra.begin(), extra.end());
    run.command = joined(args);
    run.result = runDemo(args);
    if (run.result.exitCode == 0) run.triangles = gpuFrameTriangles(bench);
    return run;
}

/// A rendered frame of the expected size showing terrain: not blank, not
/// all background.
void expectValidScreenshot(const std::string& path, uint32_t width, uint32_t height) {
    auto image = tessera::readPng(path);
    ASSERT_TRUE(image) << image.error().message;
    const auto& img = image.value();
    EXPECT_EQ(img.width, width) << path;
    EXPECT_EQ(img.height, height) << path;
    ASSERT_EQ(img.pixels.size(), size_t(width) * height * 4) << path;
    std::set<uint32_t> colours;
    size_t lit = 0;
    for (size_t i = 0; i < img.pixels.size(); i += 4) {
        const uint8_t* p = &img.pixels[i];
        colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
        lit += p[0] + p[1] + p[2] > 30;
    }
    EXPECT_GT(colours.size(), 100u) << path << " is nearly uniform";
    EXPECT_GT(lit, img.pixels.size() / 4 / 2) << path << " is mostly black";
}

void expectSuccess(const ModeRun& run) {
    ASSERT_EQ(run.result.exitCode, 0) << run.command << "\n" << run.result.output;
    EXPECT_NE(run.result.output.find("validation messages: 0"), std::string::npos) << run.command << "\n"
                                                                                   << run.result.output;
    ASSERT_TRUE(run.triangles.has_value()) << run.command << ": no gpuFrame clippingInvocations in the benchmark";
}

} // namespace

TEST(TerrainModes, AdaptiveLiesBetweenLowresAndContinuous) {
    const auto lowres = runMode("lowres", {"--terrain-mode", "lowres"});
    expectSuccess(lowres);
    const auto adaptive = runMode("adaptive", {"--terrain-mode", "adaptive"});
    expectSuccess(adaptive);
    const auto continuous = runMode("continuous", {"--terrain-mode", "continuous", "--tess-level", "32"});
    expectSuccess(continuous);
    if (HasFatalFailure()) return;

    const double low = *lowres.triangles, adapt = *adaptive.triangles, cont = *continuous.triangles;
    EXPECT_GT(low, 0.0) << lowres.command;
    EXPECT_LT(low, adapt) << "lowres " << low << " vs adaptive " << adapt;
    EXPECT_LT(adapt, cont) << "adaptive " << adapt << " vs continuous " << cont;
    EXPECT_GE(adapt, 2.0 * low) << "adaptive should at least double the control mesh: lowres " << low << ", adaptive "
                                << adapt;

    for (const auto* run : {&lowres, &adaptive, &continuous}) {
        SCOPED_TRACE(run->command);
        expectValidScreenshot(run->screenshot, 320, 180);
    }
}

TEST(TerrainModes, TessMaxCapsTheAdaptiveLevels) {
    const auto full = runMode("adaptive_full", {"--terrain-mode", "adaptive", "--tess-target", "4"});
    expectSuccess(full);
    const auto capped =
        runMode("adaptive_max1", {"--terrain-mode", "adaptive", "--tess-target", "4", "--tess-max", "1"});
    expectSuccess(capped);
    if (HasFatalFailure()) return;
    EXPECT_LT(*capped.triangles, *full.triangles) << capped.command;
}

// Every GPU backend now draws all three modes; the template plugin (which
// draws only lowres, the capabilities' default) keeps the refusal covered.
TEST(TerrainModes, LowresOnlyBackendsRefuseOtherModes) {
    const std::string templateDir = TESSERA_TEST_PLUGIN_DIR "/../tessera-template";
    for (const char* backend : {"template"}) {
        for (const char* mode : {"adaptive", "continuous"}) {
            const std::vector<std::string> args = {
                "--scene", "terrain", "--plugin-dir", templateDir, "--backend", backend, "--validation", "--terrain-mode", mode,
                "--frames",     "1",         "--width",   "64",    "--height",     "64"};
            const auto run = runDemo(args);
            SCOPED_TRACE(joined(args));
            EXPECT_EQ(run.exitCode, 1) << run.output;
            EXPECT_NE(run.output.find(backend), std::string::npos) << run.output;
            EXPECT_NE(run.output.find(std::string("--terrain-mode ") + mode), std::string::npos) << run.output;
            EXPECT_NE(run.output.find("lowres"), std::string::npos) << "should say what it does draw: " << run.output;
        }
    }
}

TEST(TerrainModes, LowresOnlyBackendDrawsLowres) {
    const std::string shot = (testOutputDir("terrain_modes") / "r2vb_lowres.png").string();
    std::filesystem::remove(shot);
    const std::vector<std::string> args = {
        "--scene", "terrain", "--backend", "r2vb",    "--validation", "--terrain-mode", "lowres", "--camera",     kCamera, "--frames",
        "1",         "--width", "320",          "--height",       "180",    "--screenshot", shot};
    const auto run = runDemo(args);
    ASSERT_EQ(run.exitCode, 0) << joined(args) << "\n" << run.output;
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;
    expectValidScreenshot(shot, 320, 180);
}

TEST(TerrainModes, LevelLimitsAreChecked) {
    for (const auto& [flag, value] : std::vector<std::pair<std::string, std::string>>{
             {"--tess-max", "80"}, {"--tess-max", "0.5"}, {"--tess-level", "65"}, {"--tess-level", "0"}}) {
        const auto run = runDemo({"--backend", "null", flag, value});
        EXPECT_EQ(run.exitCode, 2) << flag << " " << value << ": " << run.output;
        EXPECT_NE(run.output.find(flag + " expects a number from 1 to 64"), std::string::npos)
            << flag << " " << value << ": " << run.output;
    }
}
