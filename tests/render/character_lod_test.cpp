// The LOD manager in the demo: its flags fail clearly, and its frame budget
// bounds what a model costs whatever its size on screen (docs/CROWD.md,
// section 6). Counts come from the GPU's own pipeline statistics.
#include "BenchmarkJson.h"
#include "CharacterDemo.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

void expectOneLineError(const std::vector<std::string>& args, const std::string& text) {
    tessera::test::expectOneLineError(args, 2, text);
}

/// `model` alone, the camera `distance` metres from it, at 1280x720 on
/// lavapipe's default backend, with `extra` flags: the character pass's
/// triangles in the median frame.
std::optional<uint64_t> closeUpTriangles(const std::string& model, const std::string& distance,
                                         const std::vector<std::string>& extra, const std::string& name) {
    const std::string json = (testOutputDir("character_lod") / (name + ".json")).string();
    std::filesystem::remove(json);
    std::vector<std::string> args = {"--crowd", "0", "--model", model, "--orbit-distance", distance, "--frames", "3",
                                     "--validation", "--benchmark", json};
    args.insert(args.end(), extra.begin(), extra.end());
    const ProcessResult run = runDemo(args);
    EXPECT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
    EXPECT_TRUE(validationClean(run)) << demoCommandLine(args) << "\n" << run.output;
    std::string error;
    // The characters scene draws as an instanced crowd: its near tier.
    auto triangles = passTriangles(json, "crowd.near", error);
    EXPECT_TRUE(triangles) << error;
    return triangles;
}

std::string testdata(const std::string& relative) { return (sharedTestdataDir() / relative).string(); }

} // namespace

TEST(CharacterLod, BadLodFlagsFailClearly) {
    expectOneLineError({"--scene", "characters", "--lod-budget", "0"}, "a budget of zero");
    expectOneLineError({"--scene", "characters", "--lod-near", "50", "--lod-far", "80"},
                       "--lod-far 80 is above --lod-near 50");
    expectOneLineError({"--scene", "characters", "--lod-near", "big"}, "--lod-near");
    expectOneLineError({"--scene", "characters", "--lod-near-max", "-3"}, "--lod-near-max");
}

// A model filling much of the view asks for level 64 on every cage triangle;
// the budget caps the level instead (lavapipe's default: 100,000 tessellated
// triangles), and a tiny budget holds too.
TEST(CharacterLod, AModelCloseUpStaysWithinTheTriangleBudget) {
    const std::string cylinder = testdata("gltf/RiggedSimple/glTF-Binary/RiggedSimple.glb");
    const auto byDefault = closeUpTriangles(cylinder, "0.5", {}, "rigged_default");
    ASSERT_TRUE(byDefault);
    std::cout << "[lod] RiggedSimple close up: " << *byDefault << " triangles (lavapipe budget 100000)\n";
    EXPECT_LE(*byDefault, 100'000u);
    EXPECT_GT(*byDefault, 188u) << "not tessellated at all";

    const auto tiny = closeUpTriangles(cylinder, "0.5", {"--lod-budget", "5000"}, "rigged_tiny");
    ASSERT_TRUE(tiny);
    std::cout << "[lod] RiggedSimple, --lod-budget 5000: " << *tiny << " triangles\n";
    EXPECT_LE(*tiny, 5000u);

    // The measurement flag still forces its level (and lifts the budget).
    const auto forced = closeUpTriangles(cylinder, "0.5", {"--character-level", "9"}, "rigged_forced");
    ASSERT_TRUE(forced);
    EXPECT_GT(*forced, *tiny);
}
