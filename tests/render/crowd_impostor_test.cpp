// The crowd's impostor tier drawn by every GPU backend (docs/CROWD.md 6.10):
// a small crowd on magenta forced into the tier (every creature below the
// impostor threshold) shows about as many creature pixels as the same frame
// with every creature in the far tier, its pixels in the impostor tier's
// --lod-colors tint, under the validation layer; and a creature crossing
// the impostor threshold cross-fades from its far mesh to its card. Small
// images, two runs a backend and one dolly.
#include "CharacterDemo.h"
#include "CharacterHoles.h"
#include "CrowdDemo.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

/// Creature pixels (not magenta) and those tinted as the impostor tier
/// (--lod-colors: blue above red and green) or as the far tier (red above
/// green and blue).
struct Pixels {
    size_t creature = 0, impostorTint = 0, farTint = 0;
};

Pixels countPixels(const Rgba8Image& image) {
    Pixels n;
    for (size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
        const uint8_t* p = &image.pixels[i];
        if (isMagentaPixel(p)) continue;
        ++n.creature;
        n.impostorTint += p[2] > p[0] && p[2] > p[1];
        n.farTint += p[0] > p[1] && p[0] > p[2];
    }
    return n;
}

/// 200 agents seen from 12 m, at 320 x 180, every creature in one tier:
/// the impostor tier (`impostors`) or the far tier.
DemoShot crowdInOneTier(const std::string& backend, bool impostors) {
    std::vector<std::string> args = {"--scene", "crowd", "--agents", "200", "--meteors", "0", "--backend", backend,
                                     "--heightmap", smallCrowdTerrain(), "--no-terrain", "--look", "plain",
                                     "--clear-color", "1,0,1", "--lod-colors", "--orbit-distance", "12",
                                     // Nobody reaches the near or middle tier; the impostor
                                     // threshold at its most takes everybody, at 0 nobody.
                                     "--lod-near", "100000", "--lod-far", "100000", "--lod-impostor",
                                     impostors ? "100000" : "0", "--width", "320", "--height", "180", "--frames", "2"};
    const std::string name = backend + (impostors ? "_impostor.png" : "_far.png");
    return runDemoShot(args, testOutputDir("crowd_impostor") / name);
}

} // namespace

class CrowdImpostors : public ::testing::TestWithParam<std::string> {};

TEST_P(CrowdImpostors, EveryBackendDrawsTheTier) {
    const std::string backend = GetParam();
    if (!deviceRunsBackend(backend)) GTEST_SKIP() << "the device cannot run " << backend;
    const DemoShot cards = crowdInOneTier(backend, true);
    const DemoShot meshes = crowdInOneTier(backend, false);
    for (const DemoShot* shot : {&cards, &meshes}) {
        ASSERT_EQ(shot->result.exitCode, 0) << shot->command << "\n" << shot->result.output;
        EXPECT_TRUE(validationClean(shot->result)) << shot->command << "\n" << shot->result.output;
        ASSERT_TRUE(shot->image) << shot->readError;
    }
    const Pixels impostor = countPixels(*cards.image), far = countPixels(*meshes.image);
    std::cout << "[crowd impostor] " << backend << ": " << impostor.creature << " creature pixels as cards ("
              << impostor.impostorTint << " tinted as impostors), " << far.creature << " as far meshes\n";
    ASSERT_GT(far.creature, 1000u) << "the far meshes show nobody: " << meshes.command;
    // The cards show the creatures' silhouettes as baked, so about the far
    // meshes' pixels.
    const double ratio = double(impostor.creature) / double(far.creature);
    EXPECT_GT(ratio, 0.7) << cards.command;
    EXPECT_LT(ratio, 1.4) << cards.command;
    EXPECT_GT(impostor.impostorTint, impostor.creature * 9 / 10) << "not the impostor tier's tint: " << cards.command;
    EXPECT_GT(far.farTint, far.creature * 9 / 10) << "not the far tier's tint: " << meshes.command;
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, CrowdImpostors, ::testing::Values("hulldomain", "streamout", "r2vb", "meshshader"),
                         [](const auto& test) { return test.param; });

// One agent, the camera dollying from 4 to 14 m over 40 frames, tiers
// tinted: the creature leaves the far tier for the impostor tier half way,
// and the dithered cross-fade (lod_fade.glsl, as between the other tiers)
// moves a share of its pixels at a time instead of all at once.
TEST(CrowdImpostors, AFarCreatureCrossFadesIntoItsCard) {
    constexpr uint32_t kFrames = 40;
    const std::filesystem::path dir = testOutputDir("crowd_impostor") / "dolly";
    std::filesystem::remove_all(dir);
    const std::vector<std::string> args = {
        "--scene", "crowd", "--agents", "1", "--meteors", "0", "--backend", "hulldomain", "--heightmap",
        smallCrowdTerrain(), "--no-terrain", "--look", "plain", "--clear-color", "0,0,0", "--lod-colors",
        "--orbit-distance", "4:14", "--lod-near", "100000", "--lod-far", "100000", "--lod-impostor", "40",
        "--lod-fade", "8", "--width", "320", "--height", "180", "--frames", std::to_string(kFrames), "--validation",
        "--record", dir.string()};
    const ProcessResult result = runDemo(args);
    ASSERT_EQ(result.exitCode, 0) << demoCommandLine(args) << "\n" << result.output;
    EXPECT_TRUE(validationClean(result)) << result.output;
    // The impostor tier's share of the creature's pixels, frame by frame.
    std::vector<double> shares;
    for (uint32_t f = 0; f < kFrames; ++f) {
        char file[32];
        std::snprintf(file, sizeof file, "frame_%04u.png", f);
        auto image = readPng(dir / file);
        ASSERT_TRUE(image) << image.error().message;
        size_t creature = 0, impostor = 0;
        for (size_t i = 0; i + 3 < image.value().pixels.size(); i += 4) {
            const uint8_t* p = &image.value().pixels[i];
            if (p[0] + p[1] + p[2] < 30) continue;
            ++creature;
            impostor += p[2] > p[0] && p[2] > p[1];
        }
        shares.push_back(creature ? double(impostor) / double(creature) : 0.0);
    }
    double worst = 0.0;
    for (size_t f = 1; f < shares.size(); ++f) worst = std::max(worst, std::abs(shares[f] - shares[f - 1]));
    std::cout << "[crowd impostor] far to impostor: from " << shares.front() << " to " << shares.back()
              << " of the creature's pixels tinted as a card, at most " << worst << " in a frame\n";
    EXPECT_LT(shares.front(), 0.05);
    EXPECT_GT(shares.back(), 0.95);
    // Measured: at most 0.17 a frame (an eighth, and the card's pixels
    // differ from the mesh's).
    EXPECT_LT(worst, 0.3);
}

