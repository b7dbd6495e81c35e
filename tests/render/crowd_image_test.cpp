// The instanced crowd's images: a tier change cross-fades (a small share of
// the creature changes tier in any frame, where an instant switch changes
// all of it), the near tier has no
// cracks at any level on any backend, and the three backends draw the same
// crowd within the terrain's parity tolerance. All under the validation
// layer, on the 2 km crop of the content terrain.
#include "CharacterDemo.h"
#include "CharacterHoles.h"
#include "CrowdDemo.h"
#include "ImageCompare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

/// The share of the creature's pixels (those not black) tinted as the near
/// tier (green: green over 1.6 times red; the middle tier's yellow has red
/// close to green).
double nearShare(const Rgba8Image& image) {
    size_t near = 0, creature = 0;
    for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
        const int r = image.pixels[i], g = image.pixels[i + 1], b = image.pixels[i + 2];
        if (r + g + b < 30) continue;
        ++creature;
        near += 10 * g > 16 * r;
    }
    return creature ? double(near) / double(creature) : 0.0;
}

struct Recording {
    ProcessResult result;
    std::string command;
    std::vector<Rgba8Image> frames;
};

/// One agent alone on black, the camera dollying slowly in from 8 m to 5 m
/// over `frames` frames (so the motion changes few pixels a frame), every
/// frame recorded; tiers tinted (--lod-colors) so a tier change recolours the
/// creature; the near threshold is crossed half way.
Recording recordDolly(const std::string& name, const std::vector<std::string>& extra, uint32_t frames) {
    const std::filesystem::path dir = testOutputDir("crowd_image") / name;
    std::filesystem::remove_all(dir);
    std::vector<std::string> args = {"--scene",
                                     "crowd",
                                     "--agents",
                                     "1",
                                     "--meteors",
                                     "0",
                                     "--backend",
                                     "hulldomain",
                                     "--heightmap",
                                     smallCrowdTerrain(),
                                     "--no-terrain",
                                     "--look",
                                     "plain",
                                     "--clear-color",
                                     "0,0,0",
                                     "--lod-colors",
                                     "--orbit-distance",
                                     "8:5",
                                     "--lod-near",
                                     "55",
                                     "--lod-far",
                                     "10",
                                     "--width",
                                     "320",
                                     "--height",
                                     "180",
                                     "--frames",
                                     std::to_string(frames),
                                     "--validation",
                                     "--record",
                                     dir.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    Recording r;
    r.command = demoCommandLine(args);
    r.result = runDemo(args);
    if (r.result.exitCode != 0) return r;
    for (uint32_t f = 0; f < frames; ++f) {
        char file[32];
        std::snprintf(file, sizeof file, "frame_%04u.png", f);
        auto image = readPng(dir / file);
        if (!image) break;
        r.frames.push_back(std::move(image.value()));
    }
    return r;
}

/// The largest change of the near tier's share of the creature from one
/// frame to the next (the creature's own motion, walking as the camera
/// dollies, changes many pixels a frame but not their tier).
double worstTierStep(const Recording& r) {
    double worst = 0.0;
    for (size_t f = 1; f < r.frames.size(); ++f)
        worst = std::max(worst, std::abs(nearShare(r.frames[f]) - nearShare(r.frames[f - 1])));
    return worst;
}

} // namespace

// The dolly takes the agent from the far tier through the middle one to the
// near one. Switching at once recolours (and reshapes) the whole creature in
// one frame; the dithered cross-fade spreads that over its frames, so no
// frame moves more than a small share of it to the other tier.
TEST(CrowdImages, ATierChangeCrossFadesRatherThanPops) {
    constexpr uint32_t kFrames = 48;
    const Recording instant = recordDolly("instant", {"--lod-fade", "0"}, kFrames);
    ASSERT_EQ(instant.result.exitCode, 0) << instant.command << "\n" << instant.result.output;
    EXPECT_TRUE(validationClean(instant.result)) << instant.result.output;
    const Recording faded = recordDolly("faded", {"--lod-fade", "8"}, kFrames);
    ASSERT_EQ(faded.result.exitCode, 0) << faded.command << "\n" << faded.result.output;
    ASSERT_EQ(instant.frames.size(), kFrames);
    ASSERT_EQ(faded.frames.size(), kFrames);
    const double popped = worstTierStep(instant), blended = worstTierStep(faded);
    std::cout << "[crowd fade] the near tier's share of the creature's pixels changes by at most " << popped
              << " in a frame switching at once, " << blended << " cross-fading over 8 frames\n";
    // Measured: 0.995 at once; 0.13 faded (about an eighth a frame).
    EXPECT_GT(popped, 0.9) << "no tier change seen: " << instant.command;
    EXPECT_LT(blended, 0.25) << faded.command;
}

// The near tier drawn instanced at every level has no cracks: agents on
// magenta, every backend, every level forced (--character-level), with and
// without displacement. A crowd encloses background by itself (an arm
// against a body, one creature behind another), so a hole counts as a crack
// only where the bare cage (level 1, no displacement: a closed mesh drawn as
// its triangles) encloses none: no hole of two pixels or more may appear away
// from the reference's holes.
class CrowdNearCracks : public ::testing::TestWithParam<std::string> {};

namespace {

DemoShot crowdOnMagenta(const std::string& backend, const std::string& name, const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"--scene",
                                     "crowd",
                                     "--agents",
                                     "24",
                                     "--meteors",
                                     "0",
                                     "--backend",
                                     backend,
                                     "--heightmap",
                                     smallCrowdTerrain(),
                                     "--no-terrain",
                                     "--look",
                                     "plain",
                                     "--clear-color",
                                     "1,0,1",
                                     "--orbit-distance",
                                     "3",
                                     "--width",
                                     "320",
                                     "--height",
                                     "180",
                                     "--frames",
                                     "2"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runDemoShot(args, testOutputDir("crowd_image") / ("cracks_" + name + ".png"));
}

/// Whether hole `h` (pixels marked in `enclosed`) has a pixel farther than
/// `margin` from every background pixel of `bare`: background showing
/// through where the undisplaced cage covers the view.
bool showsThroughSolidCage(const HoleComponent& h, const std::vector<uint8_t>& enclosed, const Rgba8Image& bare,
                           int margin) {
    const int w = int(bare.width), height = int(bare.height);
    for (uint32_t y = h.minY; y <= h.maxY; ++y)
        for (uint32_t x = h.minX; x <= h.maxX; ++x) {
            if (!enclosed[size_t(y) * bare.width + x]) continue;
            bool nearBackground = false;
            for (int dy = -margin; dy <= margin && !nearBackground; ++dy)
                for (int dx = -margin; dx <= margin && !nearBackground; ++dx) {
                    const int nx = int(x) + dx, ny = int(y) + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= height) continue;
                    nearBackground = isMagentaPixel(&bare.pixels[(size_t(ny) * bare.width + size_t(nx)) * 4]);
                }
            if (!nearBackground) return true;
        }
    return false;
}

bool overlaps(const HoleComponent& a, const HoleComponent& b, uint32_t margin) {
    return a.minX <= b.maxX + margin && b.minX <= a.maxX + margin && a.minY <= b.maxY + margin &&
           b.minY <= a.maxY + margin;
}

} // namespace

TEST_P(CrowdNearCracks, NoHolesAtAnyLevel) {
    const std::string backend = GetParam();
    if (!deviceRunsBackend(backend)) GTEST_SKIP() << "the device cannot run " << backend;
    const DemoShot bare = crowdOnMagenta(backend, backend + "_bare", {"--character-level", "1", "--no-displacement"});
    ASSERT_EQ(bare.result.exitCode, 0) << bare.command << "\n" << bare.result.output;
    ASSERT_TRUE(bare.image) << bare.readError;
    const HoleReport reference = findHoles(*bare.image);
    const std::vector<std::vector<std::string>> cases = {{"--character-level", "1"},
                                                         {"--character-level", "3.7"},
                                                         {"--character-level", "7.5"},
                                                         {"--character-level", "14.99"},
                                                         {"--character-level", "7.5", "--no-displacement"}};
    for (const auto& extra : cases) {
        std::string name = backend;
        for (const std::string& a : extra) {
            name += '_';
            name += a.substr(a.find_first_not_of('-'));
        }
        SCOPED_TRACE(name);
        const DemoShot shot = crowdOnMagenta(backend, name, extra);
        ASSERT_EQ(shot.result.exitCode, 0) << shot.command << "\n" << shot.result.output;
        EXPECT_TRUE(validationClean(shot.result)) << shot.result.output;
        ASSERT_TRUE(shot.image) << shot.readError;
        std::vector<uint8_t> enclosed;
        const HoleReport holes = findHoles(*shot.image, &enclosed);
        const size_t drawn = size_t(320) * 180 - holes.magenta;
        size_t cracks = 0;
        for (const HoleComponent& h : holes.holes) {
            if (h.pixels < 2) continue;
            bool enclosedByTheCage = false;
            for (const HoleComponent& r : reference.holes) enclosedByTheCage = enclosedByTheCage || overlaps(h, r, 2);
            // Displacement (gear, lids) can close off a gap the bare cage
            // leaves open to the background, enclosing it without any
            // crack: a crack shows background where the bare cage is solid.
            if (!enclosedByTheCage && showsThroughSolidCage(h, enclosed, *bare.image, 2)) ++cracks;
        }
        std::cout << "[crowd cracks] " << name << ": creatures cover " << drawn << " px, " << holes.describe()
                  << "; the bare cage's: " << reference.holes.size() << "; new: " << cracks << "\n";
        EXPECT_GT(drawn, 2000u) << "too little drawn to judge: " << shot.command;
        EXPECT_EQ(cracks, 0u) << holes.describe() << " " << shot.command;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, CrowdNearCracks,
                         ::testing::Values("hulldomain", "r2vb", "streamout", "meshshader"),
                         [](const auto& param) { return param.param; });

// The same crowd, view and frame on the three backends: the emulated ones'
// images within the terrain parity test's tolerance of hulldomain's, every
// tier on screen (the terrain at the emulated tessellator's maximum level on
// all three, so it is the same ground).
TEST(CrowdImages, BackendsDrawTheSameCrowd) {
    const ImageTolerance tolerance{8, 0.0005, 0.05}; // backend_parity_test's kParityTolerance
    auto shot = [](const std::string& backend) {
        const std::vector<std::string> args = {"--scene",          "crowd",
                                               "--agents",         "600",
                                               "--meteors",        "0",
                                               "--backend",        backend,
                                               "--heightmap",      smallCrowdTerrain(),
                                               "--orbit-distance", "6",
                                               "--tess-max",       "14.99",
                                               "--width",          "320",
                                               "--height",         "180",
                                               "--frames",         "6",
                                               "--lod-near",       "60",
                                               "--lod-far",        "24"};
        return runDemoShot(args, testOutputDir("crowd_image") / ("parity_" + backend + ".png"));
    };
    const DemoShot reference = shot("hulldomain");
    ASSERT_EQ(reference.result.exitCode, 0) << reference.command << "\n" << reference.result.output;
    ASSERT_TRUE(reference.image) << reference.readError;
    for (const char* backend : {"r2vb", "streamout", "meshshader"}) {
        SCOPED_TRACE(backend);
        if (!deviceRunsBackend(backend)) continue;
        const DemoShot other = shot(backend);
        ASSERT_EQ(other.result.exitCode, 0) << other.command << "\n" << other.result.output;
        EXPECT_TRUE(validationClean(other.result)) << other.result.output;
        ASSERT_TRUE(other.image) << other.readError;
        const auto diff = testOutputDir("crowd_image") / (std::string("parity_") + backend + ".diff.png");
        const ImageComparison cmp = compareImages(*other.image, *reference.image, tolerance, diff.string());
        std::cout << "[crowd parity] " << backend << " vs hulldomain: " << cmp.differingFraction * 100.0
                  << "% of pixels differ by more than 8/255, mean difference " << cmp.meanDifference << "\n";
        EXPECT_TRUE(cmp.match) << cmp.message << " " << other.command;
    }
}
