// Swimming (issue 14; the second paper's section 6): when tessellation
// levels change, the tessellator's vertices slide over the displacement.
// Sampled at its finest mip, a displacement finer than the tessellation
// aliases: each new set of vertices picks up different bumps and the
// surface boils. Selecting (and blending) the mip from the same levels
// band-limits it to what the tessellation can carry, so the surface changes
// little. The run: a displaced cube seen as the camera circles slowly
// (0.15 rad/s) while the level sweeps from 3 to 7 over 16 frames; the
// metric: the mean absolute change of the surface's pixels between
// consecutive frames (the camera's motion adds the same to both runs),
// which must be lower with mip selection than without.
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

/// The recorded frames of one run (empty, with a failure, when it failed).
std::vector<Rgba8Image> recordRun(const std::string& backend, const std::string& tag,
                                  const std::vector<std::string>& extra) {
    const fs::path dir = testOutputDir("subdiv_swim") / (backend + "_" + tag);
    fs::remove_all(dir);
    const fs::path obj = sharedTestdataDir() / "osd_shapes" / "catmark_cube.obj";
    std::vector<std::string> args = soloCharacterArgs(backend, obj.string(), "1,0,1", "2.5", kWidth, kHeight);
    // A strong displacement, the cage still: only the camera and the levels
    // change between frames.
    args.insert(args.end(), {"--frames", std::to_string(kFrames), "--subdiv-amplitude", "0.05", "--subdiv-still",
                             "--record", dir.string(), "--validation"});
    args.insert(args.end(), extra.begin(), extra.end());
    const std::string command = demoCommandLine(args);
    const ProcessResult result = runDemo(args);
    EXPECT_EQ(result.exitCode, 0) << command << "\n" << result.output;
    EXPECT_TRUE(validationClean(result)) << command << "\n" << result.output;
    std::vector<Rgba8Image> frames;
    if (result.exitCode != 0) return frames;
    for (int f = 0; f < kFrames; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", f);
        auto image = readPng(dir / name);
        EXPECT_TRUE(image) << command << ": frame " << f;
        if (!image) return {};
        frames.push_back(std::move(image.value()));
    }
    return frames;
}

/// Mean absolute change per channel (0..255) between consecutive frames,
/// over the pixels where both show the surface.
double frameChange(const std::vector<Rgba8Image>& run) {
    double sum = 0.0;
    size_t samples = 0;
    for (int f = 1; f < kFrames; ++f) {
        const std::vector<uint8_t>& a = run[f - 1].pixels;
        const std::vector<uint8_t>& b = run[f].pixels;
        for (size_t i = 0; i + 3 < a.size(); i += 4) {
            if (isMagentaPixel(&a[i]) || isMagentaPixel(&b[i])) continue;
            for (size_t c = 0; c < 3; ++c) sum += std::abs(int(a[i + c]) - int(b[i + c]));
            samples += 3;
        }
    }
    EXPECT_GT(samples, size_t(kFrames - 1) * 3 * 3000) << "the surface is barely in view";
    return samples ? sum / double(samples) : -1.0;
}

class SubdivSwimming : public ::testing::TestWithParam<std::string> {};

} // namespace

TEST_P(SubdivSwimming, MipSelectionSwimsLessThanTheFinestLevel) {
    const std::string backend = GetParam();
    const std::vector<std::string> sweep = {"--subdiv-level", "3:7"};
    const auto withMips = recordRun(backend, "mips", sweep);
    std::vector<std::string> finestArgs = sweep;
    finestArgs.push_back("--no-mips");
    const auto finest = recordRun(backend, "finest", finestArgs);
    ASSERT_EQ(withMips.size(), size_t(kFrames));
    ASSERT_EQ(finest.size(), size_t(kFrames));
    const double mips = frameChange(withMips);
    const double fine = frameChange(finest);
    std::cout << "[subdiv swim] " << backend << ": change per frame " << mips << " with mip selection, " << fine
              << " sampling the finest level (mean per channel, 0..255)\n";
    EXPECT_LT(mips, fine) << "mip selection should swim less than sampling the finest level";
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, SubdivSwimming, ::testing::Values("hulldomain"),
                         [](const auto& test) { return test.param; });
