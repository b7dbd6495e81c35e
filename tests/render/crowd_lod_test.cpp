// The instanced crowd's GPU culling and LOD binning against the CPU
// reference: the same agents in every tier, for views inside, across and
// away from the crowd (docs/CROWD.md, section 6), under the validation layer.
#include "CrowdDemo.h"
#include "JsonReader.h"

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
    JsonValue tiers;
    std::string command;
};

/// The crowd scene on the small terrain for a few frames with `view`
/// flags, writing --crowd-tiers.
TierRun runTiers(const std::string& backend, const std::string& name, const std::vector<std::string>& view) {
    const std::string json = (testOutputDir("crowd_lod") / (name + "_" + backend + ".json")).string();
    std::filesystem::remove(json);
    std::vector<std::string> args = {"--scene",  "crowd", "--backend",    backend, "--heightmap", smallCrowdTerrain(),
                                     "--frames", "12",    "--width",      "480",   "--height",    "270",
                                     "--validation", "--crowd-tiers", json};
    args.insert(args.end(), view.begin(), view.end());
    TierRun run;
    run.command = demoCommandLine(args);
    run.result = runDemo(args);
    std::string error;
    if (run.result.exitCode == 0) {
        EXPECT_TRUE(parseJson(readTextFile(json), run.tiers, error)) << error;
    }
    return run;
}

std::vector<double> idsOf(const JsonValue& tiers, const char* source, const char* tier) {
    std::vector<double> ids;
    const JsonValue* group = tiers.find(source);
    const JsonValue* list = group ? group->find(tier) : nullptr;
    if (list && list->isArray())
        for (const JsonValue& v : list->array) ids.push_back(v.number);
    return ids;
}

} // namespace

// The GPU's lists (hulldomain's compute pass, run on the frame's instances
// against its own LOD state) hold exactly the agents the CPU reference puts
// in each tier, frame after frame, cross-fade copies included.
TEST(CrowdLod, GpuBinningEqualsTheCpuReference) {
    const std::vector<std::pair<std::string, std::vector<std::string>>> views = {
        {"inside", {"--orbit-distance", "4"}},
        {"across", {"--orbit-distance", "14"}},
        {"away", {"--camera", "0,900,0,0,80"}}};
    std::array<size_t, 3> seen{};
    for (const auto& [name, flags] : views) {
        SCOPED_TRACE(name);
        const TierRun run = runTiers("hulldomain", name, flags);
        ASSERT_EQ(run.result.exitCode, 0) << run.command << "\n" << run.result.output;
        EXPECT_TRUE(validationClean(run.result)) << run.command << "\n" << run.result.output;
        for (size_t t = 0; t < kTiers.size(); ++t) {
            const auto gpu = idsOf(run.tiers, "backendTiers", kTiers[t]);
            const auto cpu = idsOf(run.tiers, "referenceTiers", kTiers[t]);
            EXPECT_EQ(gpu, cpu) << kTiers[t] << " tier differs: " << run.command;
            seen[t] += gpu.size();
            std::cout << "[crowd lod] " << name << " " << kTiers[t] << ": " << gpu.size() << " on the GPU, "
                      << cpu.size() << " in the CPU reference\n";
        }
    }
    for (size_t t = 0; t < kTiers.size(); ++t) EXPECT_GT(seen[t], 0u) << "no view put anybody in " << kTiers[t];
}

// The null backend runs the same shared rule on the CPU on its own: its
// lists equal the LOD manager's too.
TEST(CrowdLod, NullBackendEqualsTheCpuReference) {
    const TierRun run = runTiers("null", "null", {"--orbit-distance", "6"});
    ASSERT_EQ(run.result.exitCode, 0) << run.command << "\n" << run.result.output;
    for (const char* tier : kTiers)
        EXPECT_EQ(idsOf(run.tiers, "backendTiers", tier), idsOf(run.tiers, "referenceTiers", tier)) << tier;
}

// A backend without instanced crowds says so when asked for the tiers.
TEST(CrowdLod, TiersOfABackendWithoutInstancingFailClearly) {
    const TierRun run = runTiers("r2vb", "r2vb", {});
    EXPECT_EQ(run.result.exitCode, 1) << run.result.output;
    const auto errors = errorLines(run.result.output);
    ASSERT_EQ(errors.size(), 1u) << run.result.output;
    EXPECT_NE(errors.front().find("--crowd-tiers"), std::string::npos) << errors.front();
}
