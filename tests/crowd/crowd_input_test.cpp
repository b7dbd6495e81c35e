// Bad input: every mistake gives one message naming what is wrong, or a
// defined behaviour; never a crash or a hang.

#include "CrowdTestWorld.h"

namespace tessera::crowd::test {
namespace {

std::string createError(const terrain::Terrain& ground, const CrowdSettings& settings,
                        const std::vector<GoalGroup>& goals, const std::vector<SpawnPattern>& spawns) {
    auto crowd = Crowd::create(ground, settings, goals, spawns);
    return crowd.ok() ? std::string("(created)") : crowd.error().message;
}

const std::vector<GoalGroup> kOneGoal = {{"market", Region::disc({100.0f, 100.0f}, 10.0f)}};

TEST(CrowdInput, SpawnsOutsideTheTerrainAreRefused) {
    auto ground = flatTerrain(129, 1.0f);
    const std::string error =
        createError(*ground, testSettings(), kOneGoal, {{Region::disc({500.0f, 500.0f}, 20.0f), 10, 1}});
    EXPECT_NE(error.find("spawn pattern 0"), std::string::npos) << error;
    EXPECT_NE(error.find("outside the terrain"), std::string::npos) << error;
}

TEST(CrowdInput, GoalsOutsideTheTerrainAreRefused) {
    auto ground = flatTerrain(129, 1.0f);
    const std::string error =
        createError(*ground, testSettings(), {{"far", Region::disc({-300.0f, 10.0f}, 5.0f)}}, {});
    EXPECT_NE(error.find("goal 'far'"), std::string::npos) << error;
    EXPECT_NE(error.find("outside the terrain"), std::string::npos) << error;
}

TEST(CrowdInput, SpawnsOnImpassableGroundAreRefused) {
    // A wall with no gap; spawning on the wall itself.
    auto ground = wallTerrain(129, 1.0f, 64.0f, [](float) { return false; });
    const std::string error =
        createError(*ground, testSettings(), kOneGoal, {{Region::rect({63.0f, 10.0f}, {65.0f, 100.0f}), 5, 1}});
    EXPECT_NE(error.find("spawn pattern 0"), std::string::npos) << error;
    EXPECT_NE(error.find("no walkable ground"), std::string::npos) << error;
}

TEST(CrowdInput, GoalsNobodyCanReachAreRefusedOrLeaveAgentsIdle) {
    // The goal lies beyond a wall with no gap.
    auto ground = wallTerrain(129, 1.0f, 64.0f, [](float) { return false; });
    const std::vector<SpawnPattern> west = {{Region::disc({30.0f, 64.0f}, 15.0f), 20, 1}};
    const std::string error = createError(*ground, testSettings(), kOneGoal, west);
    EXPECT_NE(error.find("from which goal 'market' can be reached"), std::string::npos) << error;

    // Asked for anyway: the agents idle where they stand, counted.
    std::vector<SpawnPattern> anyway = west;
    anyway[0].reachableOnly = false;
    auto crowd = makeCrowd(*ground, testSettings(), kOneGoal, anyway);
    ASSERT_TRUE(crowd);
    for (int s = 0; s < 60; ++s) crowd->step();
    EXPECT_EQ(crowd->stats().unreachable, 20u);
    EXPECT_EQ(crowd->stats().walking, 0u);
}

TEST(CrowdInput, MoreAgentsThanARegionHoldsAreRefused) {
    auto ground = flatTerrain(129, 1.0f);
    const std::string error =
        createError(*ground, testSettings(), kOneGoal, {{Region::disc({40.0f, 40.0f}, 5.0f), 500, 1}});
    EXPECT_NE(error.find("spawn pattern 0: 500 agents"), std::string::npos) << error;
    EXPECT_NE(error.find("do not fit"), std::string::npos) << error;
}

TEST(CrowdInput, TooManyAgentsForOneCrowdAreRefused) {
    auto ground = flatTerrain(129, 1.0f);
    SpawnPattern huge{Region::disc({40.0f, 40.0f}, 5.0f), uint32_t(Crowd::kMaxAgents), 1};
    const std::string error = createError(*ground, testSettings(), kOneGoal, {huge, huge});
    EXPECT_NE(error.find("one crowd holds at most"), std::string::npos) << error;
}

TEST(CrowdInput, BadPatternsAndSettingsAreNamed) {
    auto ground = flatTerrain(129, 1.0f);
    SpawnPattern badGroup{Region::disc({40.0f, 40.0f}, 10.0f), 5, 1, 3};
    EXPECT_NE(createError(*ground, testSettings(), kOneGoal, {badGroup}).find("goal group 3 does not exist"),
              std::string::npos);
    SpawnPattern badRadius{Region::disc({40.0f, 40.0f}, 10.0f), 5, 1};
    badRadius.radiusMin = 0.5f, badRadius.radiusMax = 0.2f;
    EXPECT_NE(createError(*ground, testSettings(), kOneGoal, {badRadius}).find("radii"), std::string::npos);
    SpawnPattern emptyRegion{Region::disc({40.0f, 40.0f}, 0.0f), 5, 1};
    EXPECT_NE(createError(*ground, testSettings(), kOneGoal, {emptyRegion}).find("positive, finite size"),
              std::string::npos);
    CrowdSettings settings = testSettings();
    settings.cellSize = 0.0f;
    EXPECT_NE(createError(*ground, settings, kOneGoal, {}).find("cellSize"), std::string::npos);
    settings = testSettings();
    settings.timeStep = NAN;
    EXPECT_NE(createError(*ground, settings, kOneGoal, {}).find("timeStep"), std::string::npos);
    EXPECT_NE(createError(*ground, testSettings(), {}, {}).find("no goal groups"), std::string::npos);
}

TEST(CrowdInput, EmptyPatternsAndGoalsInsideOtherGoalsAreFine) {
    auto ground = flatTerrain(129, 1.0f);
    // A pattern of zero agents, and agents spawned inside their goal.
    auto crowd = makeCrowd(*ground, testSettings(), {{"all", Region::rect({0.0f, 0.0f}, {128.0f, 128.0f})}},
                           {{Region::disc({60.0f, 60.0f}, 10.0f), 0, 1}, {Region::disc({60.0f, 60.0f}, 10.0f), 8, 2}});
    ASSERT_TRUE(crowd);
    for (int s = 0; s < 30; ++s) crowd->step();
    EXPECT_EQ(crowd->stats().agents, 8u);
    EXPECT_EQ(crowd->stats().staying, 8u) << "one goal to wander between: arrivals stay";
}

} // namespace
} // namespace tessera::crowd::test
