// Local avoidance and separation: dense opposing groups through a gap, and
// crossing in the open.

#include "CrowdSnapshot.h"
#include "CrowdTestWorld.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tessera::crowd::test {
namespace {

// Two groups in opposite directions cross a wall through a 16 m gap (12 m
// of it walkable: the wall's slopes take 2 m on each side): the densest
// counterflow the simulation meets. The issue's: 1,000 a side, spawned up to
// 65 m from the gap. Under the sanitizers (ten times slower) a fifth of
// them, about as dense and within 35 m of it: they still meet in the gap,
// form lanes and go through every path of the code.
struct Crossing {
#ifdef TESSERA_CROWD_SANITIZED
    static constexpr uint32_t kPerGroup = 200;
    static constexpr float kSpawnDepth = 20.0f, kSpawnHalfWidth = 16.0f;
    static constexpr uint32_t kMinThrough = 110, kMinWithinTwice = 230; // measured 138, 136 and 274
    static constexpr float kRun = 1.0f; // times the longest free walk
#else
    static constexpr uint32_t kPerGroup = 1000;
    static constexpr float kSpawnDepth = 50.0f, kSpawnHalfWidth = 40.0f;
    static constexpr uint32_t kMinThrough = 85, kMinWithinTwice = 180; // measured 103, 122 and 224
    static constexpr float kRun = 0.75f;
#endif
    std::unique_ptr<terrain::Terrain> ground =
        wallTerrain(161, 1.0f, 80.0f, [](float z) { return std::abs(z - 80.0f) < 8.0f; });
    std::vector<GoalGroup> goals = {
        {"east", Region::rect({105.0f, 30.0f}, {155.0f, 130.0f}), ArrivalPolicy::Stay},
        {"west", Region::rect({5.0f, 30.0f}, {55.0f, 130.0f}), ArrivalPolicy::Stay},
    };
    std::vector<SpawnPattern> spawns = {
        {Region::rect({65.0f - kSpawnDepth, 80.0f - kSpawnHalfWidth}, {65.0f, 80.0f + kSpawnHalfWidth}), kPerGroup, 7, 0},
        {Region::rect({95.0f, 80.0f - kSpawnHalfWidth}, {95.0f + kSpawnDepth, 80.0f + kSpawnHalfWidth}), kPerGroup, 8, 1},
    };
};

TEST(CrowdSeparation, CounterflowThroughAGapResolvesAndKeepsAgentsApart) {
    // The Froblins' own deadlock: the two groups meet in the gap. Each
    // agent's free walking time is its walk to its goal on empty ground at
    // its own speed (the potential of a crowd without agents); the issue asks
    // that 95% arrive within twice their own. The test runs for three
    // quarters of the longest free walk (65 s; sanitized, the whole of its
    // own, 54 s): both groups must be coming through, a share of them within
    // twice their own free walk already, nobody held for long, and no pair
    // overlapping by more than 5% of their radii.
    // CROWD_COUNTERFLOW_LONG=1 runs on to twice the longest free walk and
    // prints the shares through by then (docs/CROWD.md, section 5).
    Crossing world;
    auto crowd = makeCrowd(*world.ground, testSettings(), world.goals, world.spawns);
    auto empty = makeCrowd(*world.ground, testSettings(), world.goals, {});
    ASSERT_TRUE(crowd && empty);
    const CrowdAgents& a = crowd->agents();
    std::vector<float> freeTime(a.size());
    std::vector<uint8_t> arrived(a.size(), 0);
    float longest = 0.0f;
    for (size_t i = 0; i < a.size(); ++i) {
        freeTime[a.id[i]] = empty->field(a.goalGroup[i]).sample(xz(a.position[i])) / a.preferredSpeed[i];
        longest = std::max(longest, freeTime[a.id[i]]);
    }
    const bool longRun = std::getenv("CROWD_COUNTERFLOW_LONG") != nullptr;
    const float dt = crowd->settings().timeStep;
    const uint32_t settle = uint32_t(2.0f / dt), steps = uint32_t((longRun ? 2.0f : Crossing::kRun) * longest / dt);
    // Overlaps are measured every kOverlapEvery steps (every one in the
    // release build: a pair that closes in one step opens within a few).
#ifdef TESSERA_CROWD_SANITIZED
    constexpr uint32_t kOverlapEvery = 5;
#else
    constexpr uint32_t kOverlapEvery = 1;
#endif
    float worst = 0.0f, worstStuck = 0.0f;
    uint32_t worstStep = 0, through[2] = {0, 0}, withinTwice = 0, withinLongest = 0;
    for (uint32_t s = 0; s < steps; ++s) {
        crowd->step();
        if (std::getenv("CROWD_SNAPSHOTS") && s % 150 == 0) // CROWD_SNAPSHOTS=DIR: pictures to look at
            writeSnapshot(*crowd, std::string(std::getenv("CROWD_SNAPSHOTS")) + "/crossing_" + std::to_string(s) + ".png", 4.0f);
        for (size_t i = 0; i < a.size(); ++i)
            if (!arrived[a.id[i]] && world.goals[a.goalGroup[i]].region.contains(xz(a.position[i]))) {
                arrived[a.id[i]] = 1;
                ++through[a.goalGroup[i]];
                withinTwice += crowd->time() <= 2.0 * freeTime[a.id[i]];
                withinLongest += crowd->time() <= 2.0 * longest;
            }
        if (s < settle) continue;
        worstStuck = std::max(worstStuck, crowd->stats().maxStuckSeconds);
        if (s % kOverlapEvery != 0) continue;
        const OverlapReport overlap = crowd->measureOverlap();
        if (overlap.worst > worst) worst = overlap.worst, worstStep = s;
    }
    const uint32_t agents = uint32_t(a.size());
    std::printf("after %.0f s (%.1f times the longest free walk, %.1f s): %u and %u of %u through, %u of %u (%.0f%%) within "
                "twice their own free walk, %u within twice the longest; %u stuck now, longest held %.1f s; worst "
                "overlap %.3f of the sum of radii (step %u)\n",
                crowd->time(), crowd->time() / longest, double(longest), through[0], through[1], Crossing::kPerGroup,
                withinTwice, agents, 100.0 * withinTwice / agents, withinLongest, crowd->stats().stuck,
                double(worstStuck), double(worst), worstStep);
    EXPECT_LE(worst, 0.05f);
    if (longRun) return; // a report, not a test
    // Bars 15 to 20% under what is measured (docs/CROWD.md, section 4).
    // Before lanes, nobody was through by now and 712 stood still.
    EXPECT_GE(through[0], Crossing::kMinThrough) << "eastbound agents must come through";
    EXPECT_GE(through[1], Crossing::kMinThrough) << "westbound agents must come through";
    EXPECT_GE(withinTwice, Crossing::kMinWithinTwice);
    EXPECT_LT(crowd->stats().stuck, agents / 20);
    EXPECT_LT(worstStuck, 45.0f);
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
