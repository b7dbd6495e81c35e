// The instanced crowd's GPU culling and LOD binning against the CPU
// reference: the same agents in every tier, for views inside, across and
// away from the crowd (docs/CROWD.md, section 6), under the validation layer.
#include "CharacterDemo.h"
#include "CrowdDemo.h"
#include "JsonFile.h"

#include <gtest/gtest.h>

#include <array>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

constexpr std::array<const char*, 4> kTiers = {"near", "middle", "far", "impostor"};
// 2.4 m above the ground a quarter of a kilometre from the crowd, looking at
// it over a ridge 30 m above both (the small terrain): the ridge's patches'
// lowest heights hide about 700 of the 2,000 agents.
constexpr const char* kBehindHills = "918,225,1164,0,-2";

struct TierRun {
    ProcessResult result;
    nlohmann::json tiers;
    std::string command;
};

/// The crowd scene on the small terrain for a few frames with `view`
/// flags, writing --crowd-tiers.
TierRun runTiers(const std::string& backend, const std::string& name, const std::vector<std::string>& view) {
    const std::string json = (testOutputDir("crowd_lod") / (name + "_" + backend + ".json")).string();
    std::filesystem::remove(json);
    std::vector<std::string> args = {"--scene",  "crowd", "--backend",    backend, "--heightmap", smallCrowdTerrain(),
                                     "--frames", "12",    "--width",      "480",   "--height",    "270",
                                     "--validation", "--crowd-tiers", json,
                                     // Thresholds for the small frame, so every tier is seen.
                                     "--lod-near", "64", "--lod-far", "24", "--lod-impostor", "12",
                                     // No craters under the views: the tiers depend only on the camera.
                                     "--meteors", "0"};
    args.insert(args.end(), view.begin(), view.end());
    TierRun run;
    run.command = demoCommandLine(args);
    run.result = runDemo(args);
    std::string error;
    if (run.result.exitCode == 0) {
        EXPECT_TRUE(readJsonFile(json, run.tiers, error)) << error;
    }
    return run;
}

std::vector<double> idsOf(const nlohmann::json& tiers, const char* source, const char* tier) {
    std::vector<double> ids;
    const nlohmann::json* group = memberOf(tiers, source);
    const nlohmann::json* list = group ? memberOf(*group, tier) : nullptr;
    if (list && list->is_array())
        for (const nlohmann::json& v : *list) ids.push_back(v.is_number() ? v.get<double>() : 0.0);
    return ids;
}

double hiddenByTerrain(const nlohmann::json& tiers) {
    double hidden = 0.0;
    const nlohmann::json* counts = memberOf(tiers, "hiddenByTerrain");
    for (const char* tier : kTiers) {
        const nlohmann::json* n = counts ? memberOf(*counts, tier) : nullptr;
        if (n && n->is_number()) hidden += n->get<double>();
    }
    return hidden;
}

} // namespace

// Each backend's GPU culling and binning (hulldomain's and meshshader's
// compute pass, streamout's geometry shaders and stream-out, r2vb's render
// targets), run
// on the frame's instances against its own LOD state, puts exactly the
// agents the CPU reference puts in each tier, frame after frame, cross-fade
// copies included, for views inside, across and away from the crowd, and
// from low behind a ridge, where the terrain hides most of the crowd
// (horizon culling, tsLodBehindTerrain: the same agents culled everywhere).
class CrowdLodBinning : public ::testing::TestWithParam<std::string> {};

TEST_P(CrowdLodBinning, GpuBinningEqualsTheCpuReference) {
    const std::string backend = GetParam();
    if (backend != "null" && !deviceRunsBackend(backend)) GTEST_SKIP() << "the device cannot run " << backend;
    const std::vector<std::pair<std::string, std::vector<std::string>>> views = {
        {"inside", {"--orbit-distance", "4"}},
        {"across", {"--orbit-distance", "14"}},
        {"away", {"--camera", "0,900,0,0,80"}},
        {"behindHills", {"--camera", std::string(kBehindHills)}}};
    std::array<size_t, kTiers.size()> seen{};
    for (const auto& [name, flags] : views) {
        SCOPED_TRACE(name);
        const TierRun run = runTiers(backend, name, flags);
        ASSERT_EQ(run.result.exitCode, 0) << run.command << "\n" << run.result.output;
        EXPECT_TRUE(validationClean(run.result)) << run.command << "\n" << run.result.output;
        for (size_t t = 0; t < kTiers.size(); ++t) {
            const auto gpu = idsOf(run.tiers, "backendTiers", kTiers[t]);
            const auto cpu = idsOf(run.tiers, "referenceTiers", kTiers[t]);
            EXPECT_EQ(gpu, cpu) << kTiers[t] << " tier differs: " << run.command;
            seen[t] += gpu.size();
            std::cout << "[crowd lod] " << backend << " " << name << " " << kTiers[t] << ": " << gpu.size()
                      << " on the GPU, " << cpu.size() << " in the CPU reference\n";
        }
        if (name == "behindHills") {
            EXPECT_GT(hiddenByTerrain(run.tiers), 100.0) << "the ridge hides nobody";
        }
    }
    for (size_t t = 0; t < kTiers.size(); ++t) EXPECT_GT(seen[t], 0u) << "no view put anybody in " << kTiers[t];
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, CrowdLodBinning, ::testing::Values("hulldomain", "streamout", "r2vb", "meshshader", "null"),
                         [](const auto& test) { return test.param; });

// --crowd-tiers needs the crowd scene: elsewhere it is one clear error.
TEST(CrowdLod, TiersWithoutACrowdFailClearly) {
    const std::string json = (testOutputDir("crowd_lod") / "no_crowd.json").string();
    const ProcessResult result =
        runDemo({"--scene", "terrain", "--backend", "null", "--frames", "1", "--crowd-tiers", json});
    EXPECT_EQ(result.exitCode, 1) << result.output;
    const auto errors = errorLines(result.output);
    ASSERT_EQ(errors.size(), 1u) << result.output;
    EXPECT_NE(errors.front().find("--crowd-tiers"), std::string::npos) << errors.front();
}

// Horizon culling removes no visible pixel: the view from behind the ridge
// with culling and without (--no-horizon-culling) gives the same image, on a
// hardware-tessellated terrain (hulldomain, up to 64) and on the coarsest
// emulated one (r2vb, up to 14.99): the culled agents stand where every
// tessellation of the terrain hides them.
TEST(CrowdLod, HorizonCullingChangesNoPixel) {
    for (const char* backend : {"hulldomain", "r2vb"}) {
        if (!deviceRunsBackend(backend)) continue;
        SCOPED_TRACE(backend);
        std::array<std::optional<Rgba8Image>, 2> images;
        double hidden = 0.0;
        for (int culling = 0; culling < 2; ++culling) {
            const std::string name = std::string(backend) + (culling ? "_culled" : "_all");
            const std::string json = (testOutputDir("crowd_lod") / (name + ".json")).string();
            std::vector<std::string> args = {"--scene",   "crowd",      "--backend",  backend,  "--heightmap",
                                             smallCrowdTerrain(), "--frames", "12", "--width", "320",
                                             "--height",  "180",        "--meteors",  "0",      "--lod-colors",
                                             "--camera",  kBehindHills, "--crowd-tiers", json};
            if (!culling) args.push_back("--no-horizon-culling");
            const DemoShot shot = runDemoShot(args, testOutputDir("crowd_lod") / (name + ".png"));
            ASSERT_EQ(shot.result.exitCode, 0) << shot.command << "\n" << shot.result.output;
            EXPECT_TRUE(validationClean(shot.result)) << shot.command << "\n" << shot.result.output;
            ASSERT_TRUE(shot.image) << shot.readError;
            images[culling] = shot.image;
            nlohmann::json tiers;
            std::string error;
            if (culling && readJsonFile(json, tiers, error)) hidden = hiddenByTerrain(tiers);
        }
        EXPECT_GT(hidden, 100.0) << "the view culls nobody";
        EXPECT_TRUE(images[0]->pixels == images[1]->pixels) << "culling changed the image";
        std::cout << "[crowd lod] " << backend << ": " << hidden << " agents culled behind the ridge, image unchanged\n";
    }
}
