// Craters: a fresh impact is a hazard; agents near it flee, those inside walk
// out, and nobody walks in until it has cooled; once it has, its ground is
// walked over wherever its slope allows.

#include "CrowdSnapshot.h"
#include "CrowdTestWorld.h"
#include "tessera/terrain/CraterSplat.h"

#include <cstdlib>
#include <string>

#include <cstdio>

namespace tessera::crowd::test {
namespace {

struct CraterWorld {
    std::unique_ptr<terrain::Terrain> ground = flatTerrain(257, 1.0f);
    std::vector<GoalGroup> goals = {{"west", Region::disc({20.0f, 128.0f}, 10.0f)},
                                    {"east", Region::disc({236.0f, 128.0f}, 10.0f)}};
    // 600 agents walking back and forth right through where the crater lands.
    std::vector<SpawnPattern> spawns = {{Region::disc({128.0f, 128.0f}, 45.0f), 600, 21}};
};

TEST(CrowdCraters, AgentsFleeLeaveAndAvoidAFreshCrater) {
    CraterWorld world;
    CrowdSettings settings = testSettings();
    settings.hazardSeconds = 30.0f;
    auto crowd = makeCrowd(*world.ground, settings, world.goals, world.spawns);
    ASSERT_TRUE(crowd);
    for (int s = 0; s < 60; ++s) crowd->step();

    const glm::vec2 impact(128.0f, 128.0f);
    const float radius = 18.0f;
    // A shallow crater, so the ground is walkable again once it cools (the
    // demo's deep ones leave walls too steep to climb).
    world.ground->splat(impact, radius, terrain::CraterProfile{2.0f, 0.5f, 0.7f});
    crowd->step();
    const float hazard = radius + settings.hazardMargin;
    const CrowdAgents& a = crowd->agents();
    auto inside = [&](size_t i) { return glm::distance(xz(a.position[i]), impact) <= radius; };
    size_t insideAtImpact = 0;
    for (size_t i = 0; i < a.size(); ++i) insideAtImpact += inside(i);
    EXPECT_GT(insideAtImpact, 20u) << "the crater should land among the agents";
    EXPECT_GT(crowd->stats().fleeing, insideAtImpact) << "agents around the impact flee too";
    EXPECT_EQ(crowd->stats().activeHazards, 1u);

    // Walking out at ~1.3 m/s takes at most the hazard radius over the
    // slowest speed; after that nobody is inside, and nobody enters while it
    // is fresh.
    const float leave = hazard / 1.1f + 3.0f;
    std::vector<uint8_t> out(a.size(), 0); // by agent id
    for (int s = 0; s < int((settings.hazardSeconds - 1.0f) / settings.timeStep); ++s) {
        crowd->step();
        const float since = float(s + 1) * settings.timeStep;
        for (size_t i = 0; i < a.size(); ++i) {
            const uint32_t id = a.id[i];
            if (!inside(i)) {
                out[id] = 1;
                continue;
            }
            ASSERT_FALSE(out[id]) << "agent " << id << " walked into the fresh crater " << since << " s after impact";
            ASSERT_LT(since, leave) << "agent " << id << " still inside the crater " << since << " s after impact";
        }
    }
    // Cooled: the hazard is lifted and the ground is walkable again.
    for (int s = 0; s < int(2.0f / settings.timeStep); ++s) crowd->step();
    EXPECT_EQ(crowd->stats().activeHazards, 0u);
    EXPECT_TRUE(crowd->passable(impact));
    EXPECT_TRUE(crowd->field(0).reachable(impact));
}

TEST(CrowdCraters, ACraterBeforeTheCrowdIsJustGround) {
    // Craters made before the crowd existed are part of the terrain, not
    // hazards: the crowd only reacts to impacts it sees land.
    CraterWorld world;
    world.ground->splat(glm::vec2(128.0f, 40.0f), 15.0f);
    auto crowd = makeCrowd(*world.ground, testSettings(), world.goals, world.spawns);
    ASSERT_TRUE(crowd);
    crowd->step();
    EXPECT_EQ(crowd->stats().activeHazards, 0u);
    EXPECT_EQ(crowd->stats().fleeing, 0u);
}

TEST(CrowdCraters, ACraterStopsBlockingOnceItsHazardLifts) {
    // The meteor shower's smallest crater (35 m, its shape scaled: 7.7 m
    // deep, its inner wall up to 33.7 degrees as an agent measures slope)
    // lands across a valley 24 m wide, on ground sampled every 4 m like the
    // content map, in the way of 40 agents. While fresh it is a hazard;
    // once lifted it is ground again, walked over as its slope allows: the
    // valley is open and everybody gets through, over the crater, within
    // half as long again as its slopes make the walk.
    auto ground = makeTerrain(129, 4.0f, [](float, float z) {
        return std::abs(z - 234.0f) <= 4.0f || std::abs(z - 278.0f) <= 4.0f ? 70.0f : 20.0f;
    });
    CrowdSettings settings = testSettings();
    settings.cellSize = 4.0f;
    settings.hazardSeconds = 10.0f;
    const glm::vec2 impact(256.0f, 256.0f);
    const float radius = 35.0f;
    const std::vector<GoalGroup> goals = {{"east", Region::rect({330.0f, 244.0f}, {380.0f, 268.0f}), ArrivalPolicy::Stay}};
    auto crowd = makeCrowd(*ground, settings, goals, {{Region::rect({150.0f, 246.0f}, {200.0f, 266.0f}), 40, 5}});
    ASSERT_TRUE(crowd);
    crowd->step();
    ground->splat(terrain::CraterSplat{impact, radius, terrain::scaledCraterProfile(radius)});
    crowd->step();
    EXPECT_FALSE(crowd->passable(impact)) << "fresh, it is a hazard";
    for (int s = 0; s < int((settings.hazardSeconds + 1.0f) / settings.timeStep); ++s) crowd->step();
    ASSERT_EQ(crowd->stats().activeHazards, 0u);
    const glm::vec2 west(180.0f, 256.0f);
    EXPECT_TRUE(crowd->passable(impact));
    EXPECT_TRUE(crowd->field(0).reachable(west)) << "lifted, its rim must not close the valley";
    // The way over costs what its slopes cost: at most 1.5 times the flat
    // distance.
    const float way = crowd->field(0).sample(west), flat = 330.0f - west.x;
    EXPECT_LT(way, 1.5f * flat);
    uint32_t lifted = 0;
    const float bound = std::min(1.5f * crowd->field(0).sample({150.0f, 246.0f}) / SpawnPattern{}.speedMin, 600.0f);
    const uint32_t most = uint32_t(bound / settings.timeStep);
    while (crowd->stats().staying < crowd->agents().size() && lifted < most) {
        crowd->step();
        ++lifted;
        if (std::getenv("CROWD_SNAPSHOTS") && lifted % 300 == 0)
            writeSnapshot(*crowd, std::string(std::getenv("CROWD_SNAPSHOTS")) + "/crater_" + std::to_string(lifted) +
                                      ".png", 3.0f, {140.0f, 200.0f}, {390.0f, 312.0f});
    }
    std::printf("crater lifted: the way over costs %.1f for %.0f m; %u of %zu agents through %.1f s later "
                "(bound %.0f s)\n", double(way), double(flat), crowd->stats().staying, crowd->agents().size(),
                double(lifted) * settings.timeStep, double(bound));
    EXPECT_EQ(crowd->stats().staying, crowd->agents().size());
}

} // namespace
} // namespace tessera::crowd::test
