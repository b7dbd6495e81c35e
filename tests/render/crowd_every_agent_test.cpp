// Every agent in view is drawn, on every backend, whatever the budgets
// (issue 31, item 0): the budgets choose the representation (near, middle,
// far mesh, impostor card), never whether. With lavapipe's budgets (4 near,
// 64 middle, 3,000 far instances) a crowd of 10,000 or 65,000 spends the far
// budget and the rest in view are impostors; the backend's lists must hold
// exactly the agents the CPU reference counts in view.
#include "CrowdDemo.h"
#include "JsonFile.h"

#include <gtest/gtest.h>

#include <iostream>
#include <set>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

constexpr const char* kTiers[] = {"near", "middle", "far", "impostor"};

double number(const nlohmann::json& json, const char* key) {
    const nlohmann::json* n = memberOf(json, key);
    return n && n->is_number() ? n->get<double>() : -1.0;
}

} // namespace

class CrowdEveryAgent : public ::testing::TestWithParam<std::string> {};

TEST_P(CrowdEveryAgent, EveryAgentInViewIsDrawnPastEveryBudget) {
    const std::string backend = GetParam();
    if (backend != "null" && !deviceRunsBackend(backend)) GTEST_SKIP() << "the device cannot run " << backend;
    // Lavapipe's budgets, given so that every backend (the null one and a
    // GPU's too) runs them; impostors only past the far budget, so the far
    // tier fills first at this small size.
    for (const char* agents : {"10000", "65000"}) {
        SCOPED_TRACE(agents);
        const std::string json =
            (testOutputDir("crowd_every_agent") / (backend + "_" + agents + ".json")).string();
        std::filesystem::remove(json);
        const std::vector<std::string> args = {
            "--scene", "crowd", "--backend", backend, "--heightmap", smallCrowdTerrain(), "--agents", agents,
            "--frames", "3", "--width", "320", "--height", "180", "--validation", "--meteors", "0",
            // Seen from above the crowd's edge, most of it in view.
            "--camera", "918,320,1100,0,-28", "--lod-near-max", "4", "--lod-middle-max", "64", "--lod-far-max",
            "3000", "--lod-impostor", "0", "--crowd-tiers", json};
        const ProcessResult result = runDemo(args);
        ASSERT_EQ(result.exitCode, 0) << demoCommandLine(args) << "\n" << result.output;
        EXPECT_TRUE(validationClean(result)) << result.output;
        nlohmann::json tiers;
        std::string error;
        ASSERT_TRUE(readJsonFile(json, tiers, error)) << error;
        std::set<double> drawn;
        size_t far = 0, impostors = 0;
        for (const char* tier : kTiers) {
            const nlohmann::json* group = memberOf(tiers, "backendTiers");
            const nlohmann::json* list = group ? memberOf(*group, tier) : nullptr;
            ASSERT_TRUE(list && list->is_array()) << tier;
            for (const nlohmann::json& id : *list) drawn.insert(id.get<double>());
            if (std::string(tier) == "far") far = list->size();
            if (std::string(tier) == "impostor") impostors = list->size();
        }
        const double inView = number(tiers, "inView");
        std::cout << "[crowd every agent] " << backend << " " << agents << ": " << inView << " in view, "
                  << drawn.size() << " drawn (" << far << " far, " << impostors << " impostors, "
                  << number(tiers, "pastFarBudget") << " past the far budget)\n";
        EXPECT_EQ(double(drawn.size()), inView);
        EXPECT_GT(inView, 5000.0) << "the view must hold more than the far budget";
        EXPECT_LE(far, 3000u + 3000u) << "the far budget (fading copies aside)";
        EXPECT_GT(number(tiers, "pastFarBudget"), 0.0) << "the far budget must be spent for the test to mean anything";
    }
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, CrowdEveryAgent,
                         ::testing::Values("hulldomain", "streamout", "r2vb", "meshshader", "null"),
                         [](const auto& test) { return test.param; });
