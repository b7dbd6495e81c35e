// Craters: a fresh impact is a hazard; agents near it flee, those inside walk
// out, and nobody walks in until it has cooled.

#include "CrowdTestWorld.h"

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

} // namespace
} // namespace tessera::crowd::test
