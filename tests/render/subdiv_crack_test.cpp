// Watertightness of the Catmull-Clark surfaces (issue 14; the second paper
// through OpenSubdiv, docs/SUBDIV.md): every shape of OpenSubdiv's
// regression set alone on a magenta clear colour, on every backend that
// draws surfaces, its level swept over the run (--subdiv-level A:B, every
// frame recorded), base surface and displaced. OpenSubdiv's own hardware
// tessellation viewers crack along patch edges (OpenSubdiv issue 1316):
// neighbouring patches evaluate a shared edge from different control points
// and parameters. Ours evaluate every edge and corner point at its owner
// (SubdivLayout.h, tsSubdivCanonical), so a crack would be a bug. A hole is
// background the border fill cannot reach (CharacterHoles.h); closed shapes
// cull back faces, so a crack shows magenta through the body; open ones are
// drawn two-sided and seen from above, where a crack shows the background
// behind them.
#include "CharacterDemo.h"
#include "CharacterHoles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

namespace fs = std::filesystem;

// Every shape but three: catmark_hole_test1, whose holes are faces by
// design, and catmark_val2_interior and catmark_xord_interior, grids of
// separate pieces whose rims, seen obliquely, enclose background between
// pieces. Their shared edges are covered by the owner rule's CPU tests
// (SubdivDomains.*, bit-equal from both sides on every shape).
const char* const kShapes[] = {"catmark_cube",         "catmark_cube_corner4", "catmark_cube_creases1",
                               "catmark_edgecorner",   "catmark_fvar_bound0",  "catmark_nonquads",
                               "catmark_pyramid",      "catmark_single_crease", "catmark_smoothtris0"};

constexpr int kWidth = 320, kHeight = 240;
// A 1.6 m surface seen from 2.5 m covers 1,900 (a flat strip seen edge-on)
// to 20,000 of the 76,800 pixels; fewer means it went missing.
constexpr size_t kMinSurfacePixels = 1200;

struct Sweep {
    const char* levels;    ///< --subdiv-level A:B
    const char* amplitude; ///< --subdiv-amplitude
    int frames;
    const char* sculpt = nullptr; ///< --sculpt raise|lower, or none
};

/// Runs one shape through a sweep and checks every recorded frame; returns
/// the number of frames that failed.
int sweepShape(const std::string& backend, const std::string& shape, const Sweep& sweep) {
    const fs::path obj = sharedTestdataDir() / "osd_shapes" / (shape + ".obj");
    std::string tag = backend + "_" + shape + "_a" + sweep.amplitude + "_l" + sweep.levels;
    if (sweep.sculpt) tag += std::string("_") + sweep.sculpt;
    const fs::path dir = testOutputDir("subdiv_crack") / tag;
    fs::remove_all(dir);
    std::vector<std::string> args =
        soloCharacterArgs(backend, obj.string(), "1,0,1", "2.5", kWidth, kHeight);
    args.insert(args.end(), {"--frames", std::to_string(sweep.frames), "--subdiv-level", sweep.levels,
                             "--subdiv-amplitude", sweep.amplitude, "--record", dir.string(), "--validation"});
    if (sweep.sculpt) args.insert(args.end(), {"--sculpt", sweep.sculpt});
    const std::string command = demoCommandLine(args);
    const ProcessResult result = runDemo(args);
    EXPECT_EQ(result.exitCode, 0) << command << "\n" << result.output;
    EXPECT_TRUE(validationClean(result)) << command << "\n" << result.output;
    if (result.exitCode != 0) return sweep.frames;
    int failures = 0;
    for (int f = 0; f < sweep.frames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", f);
        auto image = readPng(dir / name);
        EXPECT_TRUE(image) << command << ": frame " << f << " " << (image ? "" : image.error().message);
        if (!image) {
            ++failures;
            continue;
        }
        const HoleReport holes = findHoles(image.value());
        const size_t surface = size_t(kWidth) * kHeight - holes.magenta;
        std::cout << "[subdiv crack] " << tag << " frame " << f << ": " << holes.describe() << ", surface "
                  << surface << " px\n";
        EXPECT_GT(surface, kMinSurfacePixels) << "the surface is barely in view\n  " << command;
        EXPECT_EQ(holes.holePixels, 0u) << holes.describe() << ": a crack in the surface\n  " << command
                                         << "\n  frame: " << (dir / name).string();
        failures += holes.holePixels != 0 || surface <= kMinSurfacePixels;
    }
    return failures;
}

int sweepAll(const std::string& backend, const Sweep& sweep) {
    int failures = 0;
    for (const char* shape : kShapes) {
        SCOPED_TRACE(shape);
        failures += sweepShape(backend, shape, sweep);
    }
    return failures;
}

class SubdivCrack : public ::testing::TestWithParam<std::string> {};

} // namespace

// The base surface (no displacement), levels 1 to 14.99 over five frames
// (1, 4.5, 8.0, 11.5, 14.99: fractional odd spacing in between).
TEST_P(SubdivCrack, BaseSurfaceHasNoCracksAtAnyLevel) {
    EXPECT_EQ(sweepAll(GetParam(), {"1:14.99", "0", 5}), 0);
}

// Displaced by the procedural displacement in the paper's tile format:
// tiles meet along edges with shared overlap texels and mips, and each
// edge point is displaced once, at its owner.
TEST_P(SubdivCrack, DisplacedSurfaceHasNoCracksAtAnyLevel) {
    EXPECT_EQ(sweepAll(GetParam(), {"1:14.99", "0.03", 5}), 0);
}

// After sculpt strokes (one dab a frame, re-uploading the rewritten tiles
// with their mips and the neighbours' overlaps): on quads alone, on a mesh
// with non-quads (tiles of two sizes meeting: quads 16, sub-faces 8) and on
// the pyramid's extraordinary apex.
TEST_P(SubdivCrack, SculptedSurfaceHasNoCracks) {
    int failures = 0;
    for (const char* shape : {"catmark_cube", "catmark_nonquads", "catmark_pyramid"}) {
        SCOPED_TRACE(shape);
        failures += sweepShape(GetParam(), shape, {"1:14.99", "0.02", 12, "raise"});
        failures += sweepShape(GetParam(), shape, {"14.99:3", "0.02", 12, "lower"});
    }
    EXPECT_EQ(failures, 0);
}

// hulldomain's hardware tessellator above the emulated range, to 64.
TEST(SubdivCrackHardware, DisplacedSurfaceHasNoCracksUpTo64) {
    EXPECT_EQ(sweepAll("hulldomain", {"14.99:64", "0.03", 3}), 0);
}

// meshshader's patterns from task and mesh shaders, over the whole range in
// one sweep (its patterns are the hardware's, checked bit for bit against the
// tessellator: tests/unit/tessellator_mesh_pattern_test.cpp).
TEST(SubdivCrackMesh, DisplacedSurfaceHasNoCracksUpTo64) {
    if (!deviceRunsBackend("meshshader")) GTEST_SKIP() << "the device cannot run meshshader";
    EXPECT_EQ(sweepAll("meshshader", {"1:64", "0.03", 6}), 0);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, SubdivCrack, ::testing::Values("hulldomain", "streamout", "r2vb"),
                         [](const auto& test) { return test.param; });

// The stroke shows: the last frame of a sculpted run differs from the same
// run without the brush over a band of the surface, not just a few pixels.
TEST(SubdivSculpt, TheStrokeShowsInTheNextFrames) {
    const fs::path obj = sharedTestdataDir() / "osd_shapes" / "catmark_cube.obj";
    auto shoot = [&](bool sculpt) {
        std::vector<std::string> args = soloCharacterArgs("hulldomain", obj.string(), "1,0,1", "2.5", kWidth, kHeight);
        args.insert(args.end(), {"--frames", "20", "--subdiv-still"});
        if (sculpt) args.insert(args.end(), {"--sculpt", "raise"});
        return runDemoShot(args, testOutputDir("subdiv_sculpt") / (sculpt ? "raised.png" : "plain.png"));
    };
    const DemoShot plain = shoot(false), raised = shoot(true);
    ASSERT_TRUE(plain.image && raised.image) << plain.command << "\n" << plain.result.output << "\n"
                                             << raised.command << "\n" << raised.result.output;
    EXPECT_TRUE(validationClean(raised.result)) << raised.result.output;
    size_t changed = 0;
    const std::vector<uint8_t>& a = plain.image->pixels;
    const std::vector<uint8_t>& b = raised.image->pixels;
    for (size_t i = 0; i + 3 < a.size(); i += 4) {
        int most = 0;
        for (int c = 0; c < 3; ++c) most = std::max(most, std::abs(int(a[i + c]) - int(b[i + c])));
        changed += most > 8;
    }
    std::cout << "[subdiv sculpt] " << changed << " pixels changed by the stroke\n";
    EXPECT_GT(changed, 1000u) << "the stroke barely shows\n  " << raised.command;
}
