// Crack test: a camera looking straight down on the terrain, so the terrain
// fills the screen, with a magenta clear colour. Any magenta pixel is a hole in
// the surface: a T-junction between patches whose shared edges were split
// differently, a gap at a crater's edge, or a missing patch. Swept over every
// tessellation mode, every adaptive metric, fractional targets and levels (so
// fractional_odd spacing occurs), several heights, craters and meteors, on
// every GPU backend: hulldomain with the hardware tessellator and meshshader
// with its task and mesh shaders (levels up to 64), r2vb and streamout with
// the emulated one (levels up to 14.99: their
// adaptive runs cap at --tess-max 14.99 and their continuous levels above
// 14.99 are clamped to it, so 33.3 runs as 14.99).
#include "DemoProcess.h"

#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace tessera::test;

namespace {

struct CrackCase {
    std::string name;              ///< also the screenshot's file name
    std::vector<std::string> args; ///< on top of the common arguments
};

bool isMagenta(const uint8_t* p) {
    return p[0] > 240 && p[1] < 16 && p[2] > 240;
}

size_t countMagenta(const tessera::Rgba8Image& image) {
    size_t count = 0;
    for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) count += isMagenta(&image.pixels[i]);
    return count;
}

std::string commandLine(const std::vector<std::string>& args) {
    std::string text = "tessera-demo";
    for (const auto& a : args) {
        text += ' ';
        text += shellQuote(a);
    }
    return text;
}

/// A straight-down view of the map's middle from `height` metres; the yaw
/// varies so patch edges cross the screen at different angles.
std::string downCamera(int height, int yaw = 0) {
    return "4000," + std::to_string(height) + ",4000," + std::to_string(yaw) + ",-90";
}

std::vector<std::string> commonArgs(const std::string& backend, const std::string& screenshot) {
    return {"--scene", "terrain", "--backend", backend, "--validation", "--width", "256", "--height",
            "144",       "--clear-color", "1,0,1",        "--screenshot", screenshot,
            // The plain look: the sky would paint over the clear colour cracks show.
            "--look",    "plain"};
}

/// The emulated tessellator's largest level (r2vb, streamout).
constexpr float kEmulatedMaxLevel = 14.99f;

bool emulated(const std::string& backend) {
    return backend == "r2vb" || backend == "streamout";
}

/// `args` as `backend` runs them: on the emulated backends, adaptive runs get
/// --tess-max 14.99 unless they set their own cap, and continuous levels
/// above 14.99 are clamped to it (the demo refuses a level the backend cannot
/// draw rather than clamping it silently).
std::vector<std::string> forBackend(const std::string& backend, std::vector<std::string> args) {
    if (!emulated(backend)) return args;
    auto value = [&](const std::string& flag) -> std::string* {
        auto it = std::find(args.begin(), args.end(), flag);
        return it == args.end() || it + 1 == args.end() ? nullptr : &*(it + 1);
    };
    // A copy: inserting into args would leave a pointer into it dangling.
    const std::string mode = value("--terrain-mode") ? *value("--terrain-mode") : std::string();
    if (mode == "adaptive" && !value("--tess-max")) args.insert(args.end(), {"--tess-max", "14.99"});
    if (mode == "continuous") {
        std::string* level = value("--tess-level");
        if (!level)
            args.insert(args.end(), {"--tess-level", "14.99"}); // the default, 15, is above the range
        else if (std::strtof(level->c_str(), nullptr) > kEmulatedMaxLevel)
            *level = "14.99";
    }
    return args;
}

struct CrackRun {
    std::string command;
    ProcessResult result;
    size_t magenta = 0;
    bool readable = false;
    std::string readError;
};

CrackRun runCase(const std::filesystem::path& dir, const std::string& backend, const CrackCase& c) {
    const std::string shot = (dir / (backend + "_" + c.name + ".png")).string();
    std::filesystem::remove(shot);
    std::vector<std::string> args = commonArgs(backend, shot);
    const std::vector<std::string> caseArgs = forBackend(backend, c.args);
    args.insert(args.end(), caseArgs.begin(), caseArgs.end());
    CrackRun run;
    run.command = commandLine(args);
    run.result = runDemo(args);
    if (run.result.exitCode != 0) return run;
    auto image = tessera::readPng(shot);
    if (!image) {
        run.readError = image.error().message;
        return run;
    }
    run.readable = true;
    run.magenta = countMagenta(image.value());
    return run;
}

std::vector<CrackCase> crackCases() {
    std::vector<CrackCase> cases;
    const int heights[] = {900, 1500, 2500};
    int next = 0; // cycles the heights so every metric sees each of them

    // Adaptive, every metric; the targets (or the distance metric's range) are
    // fractional so fractional levels and odd/even transitions occur.
    for (const char* metric : {"screen", "silhouette", "detail"}) {
        for (const char* target : {"2.3", "5.5", "13.7"}) {
            const int h = heights[next++ % 3];
            cases.push_back({std::string("adaptive_") + metric + "_t" + target + "_h" + std::to_string(h),
                             {"--frames", "1", "--terrain-mode", "adaptive", "--tess-metric", metric, "--tess-target",
                              target, "--camera", downCamera(h, next * 23)}});
        }
    }
    for (const char* range : {"1500.5", "4000", "9333.3"}) {
        const int h = heights[next++ % 3];
        cases.push_back({std::string("adaptive_distance_d") + range + "_h" + std::to_string(h),
                         {"--frames", "1", "--terrain-mode", "adaptive", "--tess-metric", "distance", "--tess-distance",
                          range, "--camera", downCamera(h, next * 23)}});
    }
    // A fractional cap: levels clamp at 7.5 in the middle of the view.
    cases.push_back({"adaptive_screen_max7.5_h900",
                     {"--frames", "1", "--terrain-mode", "adaptive", "--tess-metric", "screen", "--tess-target", "1.5",
                      "--tess-max", "7.5", "--camera", downCamera(900)}});

    // Continuous: one level everywhere, including fractional ones.
    for (const char* level : {"1", "3.7", "14.99", "33.3"}) {
        const int h = heights[next++ % 3];
        cases.push_back(
            {std::string("continuous_l") + level + "_h" + std::to_string(h),
             {"--frames", "1", "--terrain-mode", "continuous", "--tess-level", level, "--camera", downCamera(h)}});
    }

    // Low resolution: the control mesh alone.
    for (int h : {900, 2500})
        cases.push_back(
            {"lowres_h" + std::to_string(h), {"--frames", "1", "--terrain-mode", "lowres", "--camera", downCamera(h)}});

    // Craters in view: splats before the first frame, adaptive and continuous.
    const std::vector<std::string> craters = {"--splat", "4000,4000,150", "--splat", "4150,3900,90"};
    for (const char* mode : {"adaptive", "continuous"}) {
        CrackCase c{std::string("splat_") + mode + "_h1500",
                    {"--frames", "1", "--terrain-mode", mode, "--camera", downCamera(1500)}};
        c.args.insert(c.args.end(), craters.begin(), craters.end());
        cases.push_back(c);
    }

    // Meteors land during the run (around the camera's aim point); crater or
    // not, the surface must stay closed.
    cases.push_back({"meteors_adaptive_h1500",
                     {"--frames", "20", "--meteors", "8", "--seed", "5", "--terrain-mode", "adaptive", "--camera",
                      downCamera(1500)}});
    return cases;
}

std::filesystem::path outputDir() {
    const std::filesystem::path dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "terrain_crack";
    std::filesystem::create_directories(dir);
    return dir;
}

class TerrainCrack : public ::testing::TestWithParam<std::string> {};

} // namespace

// The detector itself: with the horizon in view the magenta sky is counted, so
// a zero count below means a closed surface, not a broken detector.
TEST(TerrainCrackDetector, SeesTheClearColour) {
    const auto run =
        runCase(outputDir(), "hulldomain", {"detector_horizon", {"--frames", "1", "--camera", "4000,900,4000,0,5"}});
    ASSERT_EQ(run.result.exitCode, 0) << run.command << "\n" << run.result.output;
    ASSERT_TRUE(run.readable) << run.readError;
    EXPECT_GT(run.magenta, 256u * 144u / 10u) << run.command;
}

TEST_P(TerrainCrack, NoHolesInAnyModeMetricOrLevel) {
    const std::string backend = GetParam();
    const auto dir = outputDir();
    const auto cases = crackCases();
    int failures = 0;
    for (const auto& c : cases) {
        const auto run = runCase(dir, backend, c);
        if (deviceCannotRun(run.result)) GTEST_SKIP() << backend << ": the device cannot run it\n" << run.result.output;
        const bool ok = run.result.exitCode == 0 && run.readable && run.magenta == 0 &&
                        run.result.output.find("validation messages: 0") != std::string::npos;
        failures += !ok;
        EXPECT_EQ(run.result.exitCode, 0) << c.name << ": " << run.command << "\n" << run.result.output;
        if (run.result.exitCode != 0) continue;
        EXPECT_NE(run.result.output.find("validation messages: 0"), std::string::npos)
            << c.name << ": " << run.command << "\n"
            << run.result.output;
        EXPECT_TRUE(run.readable) << c.name << ": " << run.command << ": " << run.readError;
        EXPECT_EQ(run.magenta, 0u) << c.name << ": " << run.magenta << " magenta (background) pixels, a crack or hole"
                                   << "\n  " << run.command;
    }
    EXPECT_EQ(failures, 0) << failures << " of " << cases.size() << " runs failed on " << backend;
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, TerrainCrack, ::testing::Values("hulldomain", "r2vb", "streamout", "meshshader"),
                         [](const auto& test) { return test.param; });
