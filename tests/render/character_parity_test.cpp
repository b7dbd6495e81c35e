// Backend parity for characters: one posed creature (frame 2 of its first
// clip) drawn by hulldomain (hardware tessellator, compute skinning), r2vb
// (render-target skinning, emulated tessellator) and streamout (transform
// feedback skinning, emulated tessellator) at a level all three can draw.
// The triangles of the tessellation pass (the pipeline statistics' clipping
// invocations, from --benchmark) must be equal and the images must match
// within kParityTolerance. The two-pass path (cage skinned once into 128-bit
// compressed vertices) must also agree closely with the single-pass path
// (every tessellated vertex skinned from the uncompressed cage), and the
// whole characters scene must run cleanly on every backend.
#include "BenchmarkJson.h"
#include "CharacterDemo.h"
#include "ImageCompare.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

// Measured on lavapipe at 320x240 (76,800 pixels), level 7.5, two-pass
// (605,000 triangles on every backend): r2vb and streamout against
// hulldomain, 5 pixels differ at all, each by 1/255, mean difference
// 0.00004. The bound allows 15 pixels (0.02%) to differ by more than 8/255
// and a mean of 0.01. A level change from 7.5 to 7.9 on hulldomain alone gives
// 0.10% and 0.10 (DetectsAChangedLevel), 5x and 10x outside it.
const ImageTolerance kParityTolerance{8, 0.0002, 0.01};
// Two-pass against single-pass on hulldomain: the compressed vertex rounds
// positions to 16 bits of the box and the frame to 8 to 11 bits, so shading
// and silhouettes move slightly. Measured: 1,052 pixels differ at all, 4
// (0.005%) by more than 24/255 (at most 114, silhouette pixels), mean 0.011.
// The bound allows 0.1% (77 pixels) and a mean of 0.1.
const ImageTolerance kPathTolerance{24, 0.001, 0.1};

struct ParityRun {
    DemoShot shot;
    std::optional<uint64_t> triangles; ///< clipping invocations of the tessellation pass
    std::string error;                 ///< why `triangles` is missing
};

/// The pass that tessellates the creature: the characters scene draws
/// two-pass as an instanced crowd (every GPU backend has them).
std::string tessellationPass(const std::string& /*backend*/, const std::string& path) {
    return path == "two-pass" ? "crowd.near" : "character.singlePass";
}

ParityRun runPoseAnew(const std::string& backend, const std::string& path, const std::string& level) {
    const auto dir = testOutputDir("character_parity");
    const std::string stem = (dir / (backend + "_" + path + "_l" + level)).string();
    std::vector<std::string> args = soloCharacterArgs(backend, froblinFile(1), "0.2,0.3,0.4", "1.0", kWidth, kHeight);
    args.insert(args.end(),
                {"--frames", "3", "--character-path", path, "--character-level", level, "--benchmark", stem + ".json"});
    ParityRun run;
    std::filesystem::remove(stem + ".json");
    run.shot = runDemoShot(args, stem + ".png");
    if (run.shot.result.exitCode == 0)
        run.triangles = passTriangles(stem + ".json", tessellationPass(backend, path), run.error);
    return run;
}

/// The posed run of `backend`, `path` and `level`, made once per process:
/// three tests read hulldomain's two-pass run at 7.5, and the suite runs as
/// one ctest test (tests/CMakeLists.txt), so it is drawn once.
const ParityRun& runPosed(const std::string& backend, const std::string& path, const std::string& level) {
    static std::map<std::string, ParityRun> runs;
    const std::string key = backend + " " + path + " " + level;
    auto it = runs.find(key);
    if (it == runs.end()) it = runs.emplace(key, runPoseAnew(backend, path, level)).first;
    return it->second;
}

/// Asserts a clean run: exit 0, no validation messages, a screenshot.
void expectClean(const ParityRun& run) {
    EXPECT_EQ(run.shot.result.exitCode, 0) << run.shot.command << "\n" << run.shot.result.output;
    EXPECT_TRUE(validationClean(run.shot.result)) << run.shot.command << "\n" << run.shot.result.output;
    EXPECT_TRUE(run.shot.image) << run.shot.command << ": " << run.shot.readError;
}

/// How many pixels differ at all and by how much at most, for the log.
std::string deltaFigures(const Rgba8Image& a, const Rgba8Image& b, const ImageComparison& cmp, int threshold) {
    size_t any = 0;
    int worst = 0;
    for (size_t p = 0; p + 3 < a.pixels.size() && p + 3 < b.pixels.size(); p += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixels[p + c]) - int(b.pixels[p + c])));
        any += d > 0;
        worst = std::max(worst, d);
    }
    std::ostringstream out;
    out << any << " pixels differ at all (max channel difference " << worst << "), " << cmp.differingFraction * 100.0
        << "% by more than " << threshold << ", mean difference " << cmp.meanDifference;
    return out.str();
}

/// Compares `actual` with `expected` under `tolerance`, printing the figures.
void expectImagesMatch(const ParityRun& actual, const ParityRun& expected, const ImageTolerance& tolerance,
                       const std::string& label) {
    if (!actual.shot.image || !expected.shot.image) return;
    const std::string diff = (testOutputDir("character_parity") / (label + ".diff.png")).string();
    std::filesystem::remove(diff);
    const auto cmp = compareImages(*actual.shot.image, *expected.shot.image, tolerance, diff);
    std::cout << "[character parity] " << label << ": "
              << deltaFigures(*actual.shot.image, *expected.shot.image, cmp, tolerance.channelThreshold) << "\n";
    EXPECT_TRUE(cmp.match) << label << ": " << cmp.message << "\n  " << actual.shot.command << "\n  "
                           << expected.shot.command;
}

} // namespace

TEST(CharacterParity, EmulatedBackendsMatchHulldomain) {
    const ParityRun reference = runPosed("hulldomain", "two-pass", "7.5");
    expectClean(reference);
    ASSERT_TRUE(reference.triangles) << reference.shot.command << ": " << reference.error;
    ASSERT_GT(*reference.triangles, 0u);
    for (const char* backend : {"r2vb", "streamout"}) {
        SCOPED_TRACE(backend);
        const ParityRun run = runPosed(backend, "two-pass", "7.5");
        expectClean(run);
        EXPECT_TRUE(run.triangles) << run.shot.command << ": " << run.error;
        if (run.triangles) {
            EXPECT_EQ(*run.triangles, *reference.triangles)
                << backend << " sends " << *run.triangles << " triangles to the clipper, hulldomain "
                << *reference.triangles << "\n  " << run.shot.command;
        }
        expectImagesMatch(run, reference, kParityTolerance, std::string(backend) + "_vs_hulldomain");
    }
    std::cout << "[character parity] crowd.near triangles: " << *reference.triangles << "\n";
}

// meshshader against hulldomain on both paths. Two-pass, both draw the
// creature as an instanced crowd's near tier (hull/domain stages against
// the character task and mesh shaders' crowd variant): the same cage, level
// and patterns, so the same triangles (clipping invocations against mesh
// primitives).
TEST(CharacterParity, MeshshaderMatchesHulldomain) {
    const ParityRun probe = runPosed("meshshader", "single-pass", "7.5");
    if (deviceCannotRun(probe.shot.result)) GTEST_SKIP() << "the device cannot run meshshader";
    for (const char* path : {"single-pass", "two-pass"}) {
        SCOPED_TRACE(path);
        const ParityRun& reference = runPosed("hulldomain", path, "7.5");
        const ParityRun& run = runPosed("meshshader", path, "7.5");
        expectClean(reference);
        expectClean(run);
        if (run.triangles && reference.triangles) {
            EXPECT_EQ(*run.triangles, *reference.triangles) << run.shot.command << "\n  " << reference.shot.command;
        }
        expectImagesMatch(run, reference, kParityTolerance, std::string("meshshader_") + path + "_vs_hulldomain");
    }
}

TEST(CharacterParity, TwoPassMatchesSinglePass) {
    const ParityRun twoPass = runPosed("hulldomain", "two-pass", "7.5");
    const ParityRun singlePass = runPosed("hulldomain", "single-pass", "7.5");
    expectClean(twoPass);
    expectClean(singlePass);
    if (twoPass.triangles && singlePass.triangles) {
        EXPECT_EQ(*twoPass.triangles, *singlePass.triangles)
            << twoPass.shot.command << "\n  " << singlePass.shot.command;
    }
    expectImagesMatch(twoPass, singlePass, kPathTolerance, "two-pass_vs_single-pass");
}

// The tolerance is not vacuous: a changed level on one backend exceeds it.
TEST(CharacterParity, DetectsAChangedLevel) {
    const ParityRun base = runPosed("hulldomain", "two-pass", "7.5");
    const ParityRun moved = runPosed("hulldomain", "two-pass", "7.9");
    expectClean(base);
    expectClean(moved);
    ASSERT_TRUE(base.shot.image && moved.shot.image);
    const std::string diff = (testOutputDir("character_parity") / "sensitivity.diff.png").string();
    const auto cmp = compareImages(*moved.shot.image, *base.shot.image, kParityTolerance, diff);
    std::cout << "[character parity] level 7.9 vs 7.5: "
              << deltaFigures(*moved.shot.image, *base.shot.image, cmp, kParityTolerance.channelThreshold) << "\n";
    EXPECT_FALSE(cmp.match) << "a level change went unnoticed";
}

// The characters scene as the issue checks it (crowd, CesiumMan, terrain),
// a few frames on every backend, under the validation layer.
TEST(CharacterParity, CharactersSceneRunsOnEveryBackend) {
    for (const char* backend : {"hulldomain", "r2vb", "streamout", "meshshader"}) {
        const std::vector<std::string> args = {"--scene", "characters", "--backend", backend, "--frames",    "3",
                                               "--width", "320",        "--height",  "240",   "--validation"};
        const auto run = runDemo(args);
        EXPECT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
        EXPECT_TRUE(validationClean(run)) << demoCommandLine(args) << "\n" << run.output;
    }
}
