// Local avoidance and separation: dense opposing groups through a gap.

#include "CrowdSnapshot.h"
#include "CrowdTestWorld.h"

#include <cstdlib>

#include <cstdio>

namespace tessera::crowd::test {
namespace {

// 2,000 agents in two groups of 1,000 cross a wall through a 16 m gap in
// opposite directions: the densest counterflow the simulation meets.
struct Crossing {
    std::unique_ptr<terrain::Terrain> ground =
        wallTerrain(161, 1.0f, 80.0f, [](float z) { return std::abs(z - 80.0f) < 8.0f; });
    std::vector<GoalGroup> goals = {
        {"east", Region::rect({105.0f, 30.0f}, {155.0f, 130.0f}), ArrivalPolicy::Stay},
        {"west", Region::rect({5.0f, 30.0f}, {55.0f, 130.0f}), ArrivalPolicy::Stay},
    };
    std::vector<SpawnPattern> spawns = {
        {Region::rect({15.0f, 40.0f}, {65.0f, 120.0f}), 1000, 7, 0},
        {Region::rect({95.0f, 40.0f}, {145.0f, 120.0f}), 1000, 8, 1},
    };
};

TEST(CrowdSeparation, DenseCrossingThroughAGapKeepsAgentsApart) {
    Crossing world;
    auto crowd = makeCrowd(*world.ground, testSettings(), world.goals, world.spawns);
    ASSERT_TRUE(crowd);
    const float dt = crowd->settings().timeStep;
    const uint32_t settle = uint32_t(2.0f / dt), steps = uint32_t(45.0f / dt);
    float worst = 0.0f;
    uint32_t worstStep = 0;
    for (uint32_t s = 0; s < steps; ++s) {
        crowd->step();
        if (std::getenv("CROWD_SNAPSHOTS") && s % 150 == 0) // CROWD_SNAPSHOTS=DIR: pictures to look at
            writeSnapshot(*crowd, std::string(std::getenv("CROWD_SNAPSHOTS")) + "/crossing_" + std::to_string(s) + ".png", 4.0f);
        if (s < settle) continue;
        const OverlapReport overlap = crowd->measureOverlap();
        if (overlap.worst > worst) worst = overlap.worst, worstStep = s;
    }
    const CrowdStats& stats = crowd->stats();
    std::printf("worst overlap %.3f of the sum of radii (step %u); %u of 2000 staying at their goal, %u stuck, "
                "max stuck %.1f s\n", double(worst), worstStep, stats.staying, stats.stuck, double(stats.maxStuckSeconds));
    EXPECT_LE(worst, 0.05f);
}

TEST(CrowdSeparation, HeadingsTurnSmoothlyWithoutJitter) {
    // Two groups of 300 cross in the open: plenty of avoiding to do.
    auto ground = flatTerrain(161, 1.0f);
    const std::vector<GoalGroup> goals = {
        {"east", Region::rect({125.0f, 40.0f}, {155.0f, 120.0f}), ArrivalPolicy::Stay},
        {"west", Region::rect({5.0f, 40.0f}, {35.0f, 120.0f}), ArrivalPolicy::Stay}};
    const std::vector<SpawnPattern> spawns = {{Region::rect({20.0f, 55.0f}, {50.0f, 105.0f}), 300, 3, 0},
                                              {Region::rect({110.0f, 55.0f}, {140.0f, 105.0f}), 300, 4, 1}};
    auto crowd = makeCrowd(*ground, testSettings(), goals, spawns);
    ASSERT_TRUE(crowd);
    const CrowdAgents& a = crowd->agents();
    const float dt = crowd->settings().timeStep;
    const float maxTurn = crowd->settings().maxTurnRate * dt;
    std::vector<float> heading(a.size()), turn(a.size(), 0.0f); // by agent id
    for (size_t i = 0; i < a.size(); ++i) heading[a.id[i]] = a.heading[i];
    uint64_t walkingSteps = 0, reversals = 0;
    double turned = 0.0;
    for (int s = 0; s < int(60.0f / dt); ++s) {
        crowd->step();
        for (size_t i = 0; i < a.size(); ++i) {
            const uint32_t id = a.id[i];
            float t = a.heading[i] - heading[id];
            t -= 6.2831853f * std::round(t / 6.2831853f);
            ASSERT_LE(std::abs(t), maxTurn * 1.0001f) << "agent " << id << " turned faster than maxTurnRate";
            heading[id] = a.heading[i];
            if (a.clip[i] != AgentClip::Walk) continue;
            ++walkingSteps;
            turned += std::abs(t);
            // A reversal: turning one way by more than a degree, then the
            // other way by more than a degree the next step.
            if (std::abs(t) > 0.0175f && std::abs(turn[id]) > 0.0175f && (t > 0.0f) != (turn[id] > 0.0f)) ++reversals;
            turn[id] = t;
        }
    }
    const double meanTurnDegrees = 57.29578 * turned / double(walkingSteps);
    const double reversalRate = double(reversals) / double(walkingSteps);
    std::printf("walking agents turn %.2f degrees per step on average; %.3f%% of steps reverse the turn\n",
                meanTurnDegrees, 100.0 * reversalRate);
    EXPECT_LT(meanTurnDegrees, 1.0);
    EXPECT_LT(reversalRate, 0.01);
}

} // namespace
} // namespace tessera::crowd::test
