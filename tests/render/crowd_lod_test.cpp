// The instanced crowd's GPU culling and LOD binning against the CPU
// reference: the same agents in every tier, for views inside, across and
// away from the crowd (docs/CROWD.md, section 6), under the validation layer.
#include "CrowdDemo.h"
#include "JsonFile.h"

#include <gtest/gtest.h>

#include <array>
#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

constexpr std::array<const char*, 3> kTiers = {"near", "middle", "far"};

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
                                     "--lod-near", "64", "--lod-far", "24",
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

} // namespace

// Each backend's GPU culling and binning (hulldomain's and meshshader's
// compute pass, streamout's geometry shaders and stream-out, r2vb's render
// targets), run
// on the frame's instances against its own LOD state, puts exactly the
// agents the CPU reference puts in each tier, frame after frame, cross-fade
// copies included, for views inside, across and away from the crowd.
class CrowdLodBinning : public ::testing::TestWithParam<std::string> {};

TEST_P(CrowdLodBinning, GpuBinningEqualsTheCpuReference) {
    const std::string backend = GetParam();
    if (backend != "null" && !deviceRunsBackend(backend)) GTEST_SKIP() << "the device cannot run " << backend;
    const std::vector<std::pair<std::string, std::vector<std::string>>> views = {
        {"inside", {"--orbit-distance", "4"}},
        {"across", {"--orbit-distance", "14"}},
        {"away", {"--camera", "0,900,0,0,80"}}};
    std::array<size_t, 3> seen{};
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
