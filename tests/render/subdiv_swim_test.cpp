// Swimming (issue 14; the second paper's section 6): as the camera moves
// slowly towards a displaced surface, its per-vertex tessellation levels
// change every frame, so the tessellator's vertices slide over the
// displacement. Sampled at the finest mip, a displacement finer than the
// tessellation aliases and the surface visibly boils; selecting (and
// blending) the mip level from the same per-vertex levels band-limits it to
// what the tessellation can carry, so it changes smoothly. The metric: the
// mean absolute change of the surface's pixels between consecutive frames
// (the camera's motion adds the same to both runs), which must be lower
// with mip selection than without.
#include "CharacterDemo.h"
#include "CharacterHoles.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 320, kHeight = 240, kFrames = 16;

/// Mean absolute channel change per surface pixel between consecutive
/// recorded frames; a negative value when the run failed (with a failure).
double swimming(const std::string& backend, bool mips) {
    const std::string tag = backend + (mips ? "_mips" : "_finest");
    const fs::path dir = testOutputDir("subdiv_swim") / tag;
    fs::remove_all(dir);
    const fs::path obj = sharedTestdataDir() / "osd_shapes" / "catmark_cube.obj";
    std::vector<std::string> args = soloCharacterArgs(backend, obj.string(), "1,0,1", "3.5:2.0", kWidth, kHeight);
    // Coarse levels (12 px per segment) under a strong displacement, the
    // cage still: only the camera and the levels change.
    args.insert(args.end(), {"--frames", std::to_string(kFrames), "--subdiv-pixels", "12", "--subdiv-amplitude",
                             "0.05", "--subdiv-still", "--record", dir.string(), "--validation"});
    if (!mips) args.push_back("--no-mips");
    const std::string command = demoCommandLine(args);
    const ProcessResult result = runDemo(args);
    EXPECT_EQ(result.exitCode, 0) << command << "\n" << result.output;
    EXPECT_TRUE(validationClean(result)) << command << "\n" << result.output;
    if (result.exitCode != 0) return -1.0;
    std::vector<Rgba8Image> frames;
    for (int f = 0; f < kFrames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", f);
        auto image = readPng(dir / name);
        EXPECT_TRUE(image) << command << ": frame " << f;
        if (!image) return -1.0;
        frames.push_back(std::move(image.value()));
    }
    double sum = 0.0;
    size_t pixels = 0;
    for (int f = 1; f < kFrames; ++f) {
        const std::vector<uint8_t>& a = frames[f - 1].pixels;
        const std::vector<uint8_t>& b = frames[f].pixels;
        for (size_t i = 0; i + 3 < a.size(); i += 4) {
            // The surface's pixels in both frames (the silhouette's own
            // motion is the camera's, not swimming).
            if (isMagentaPixel(&a[i]) || isMagentaPixel(&b[i])) continue;
            for (int c = 0; c < 3; ++c) sum += std::abs(int(a[i + c]) - int(b[i + c]));
            ++pixels;
        }
    }
    EXPECT_GT(pixels, size_t(kFrames - 1) * 3000) << "the surface is barely in view\n  " << command;
    const double metric = pixels ? sum / double(pixels * 3) : -1.0;
    std::cout << "[subdiv swim] " << tag << ": mean change " << metric << " per channel over " << pixels
              << " surface pixels\n  " << command << "\n";
    return metric;
}

class SubdivSwimming : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(SubdivSwimming, MipSelectionSwimsLessThanTheFinestLevel) {
    const double withMips = swimming(GetParam(), true);
    const double finest = swimming(GetParam(), false);
    ASSERT_GE(withMips, 0.0);
    ASSERT_GE(finest, 0.0);
    EXPECT_LT(withMips, finest) << "mip selection should swim less than sampling the finest level";
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, SubdivSwimming, ::testing::Values("hulldomain"),
                         [](const auto& test) { return test.param; });
