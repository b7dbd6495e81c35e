// Progress: agents reach their goals in the open, get through bottlenecks
// and do not deadlock at small goals (the Froblins' known failure).

#include "CrowdSnapshot.h"
#include "CrowdTestWorld.h"

#include <cstdlib>
#include <string>

#include <algorithm>
#include <cstdio>

namespace tessera::crowd::test {
namespace {

// Steps `crowd` for `seconds`, and returns when each agent (by id) first
// stood in its goal (negative: never).
std::vector<float> arrivalTimes(Crowd& crowd, float seconds, float* worstStuck = nullptr) {
    std::vector<float> arrived(crowd.agents().size(), -1.0f);
    const uint32_t steps = uint32_t(seconds / crowd.settings().timeStep);
    size_t left = arrived.size();
    for (uint32_t s = 0; s < steps && left > 0; ++s) {
        crowd.step();
        const CrowdAgents& a = crowd.agents();
        for (size_t i = 0; i < a.size(); ++i)
            if (arrived[a.id[i]] < 0.0f && crowd.goals()[a.goalGroup[i]].region.contains(xz(a.position[i])))
                arrived[a.id[i]] = float(crowd.time()), --left;
        if (worstStuck) *worstStuck = std::max(*worstStuck, crowd.stats().maxStuckSeconds);
        if (std::getenv("CROWD_SNAPSHOTS") && s % 300 == 0)
            writeSnapshot(crowd, std::string(std::getenv("CROWD_SNAPSHOTS")) + "/progress_" + std::to_string(s) + ".png");
    }
    return arrived;
}

TEST(CrowdProgress, AgentsReachTheirGoalsInTheOpen) {
    // 600 agents from a central disc to four goals 70 m away.
    auto ground = flatTerrain(257, 1.0f);
    const glm::vec2 centre(128.0f, 128.0f);
    std::vector<GoalGroup> goals;
    for (int g = 0; g < 4; ++g) {
        const float angle = 1.5707963f * float(g) + 0.4f;
        goals.push_back({"goal", Region::disc(centre + 70.0f * glm::vec2(std::cos(angle), std::sin(angle)), 10.0f),
                         ArrivalPolicy::Stay});
    }
    const SpawnPattern spawn{Region::disc(centre, 25.0f), 600, 11};
    auto crowd = makeCrowd(*ground, testSettings(), goals, {spawn});
    ASSERT_TRUE(crowd);
    // The bound: the longest start-to-goal walk at the slowest preferred
    // speed, plus half again for crowding on the way.
    const float bound = 1.5f * (70.0f + 25.0f - 10.0f) / spawn.speedMin;
    const std::vector<float> arrived = arrivalTimes(*crowd, bound);
    const size_t made = size_t(std::count_if(arrived.begin(), arrived.end(), [](float t) { return t >= 0.0f; }));
    std::printf("%zu of %zu agents arrived within %.0f s\n", made, arrived.size(), double(bound));
    EXPECT_GE(made, arrived.size() * 95 / 100);
}

TEST(CrowdProgress, NobodyStaysStuckInABottleneck) {
    // 400 agents funnel through a 6 m gap in a wall to a goal beyond it.
    auto ground = wallTerrain(161, 1.0f, 80.0f, [](float z) { return std::abs(z - 80.0f) < 5.0f; });
    const std::vector<GoalGroup> goals = {{"beyond", Region::rect({110.0f, 40.0f}, {150.0f, 120.0f}), ArrivalPolicy::Stay}};
    const SpawnPattern spawn{Region::rect({20.0f, 50.0f}, {60.0f, 110.0f}), 400, 5, 0};
    auto crowd = makeCrowd(*ground, testSettings(), goals, {spawn});
    ASSERT_TRUE(crowd);
    float worstStuck = 0.0f;
    const std::vector<float> arrived = arrivalTimes(*crowd, 240.0f, &worstStuck);
    const size_t made = size_t(std::count_if(arrived.begin(), arrived.end(), [](float t) { return t >= 0.0f; }));
    std::printf("%zu of %zu through the gap; longest without progress %.1f s\n", made, arrived.size(),
                double(worstStuck));
    EXPECT_EQ(made, arrived.size());
    // Queueing is slow progress, not none. The group takes about 100 s to
    // drain through the gap; the last in line wait up to a third of that
    // before they move a metre. A deadlock would never end.
    EXPECT_LT(worstStuck, 45.0f);
}

TEST(CrowdProgress, ASmallGoalDoesNotDeadlockTheCrowd) {
    // The Froblins' failure: everybody heading for one small spot. Goals are
    // regions, and arrivals walk on to a spot of their own inside.
    auto ground = flatTerrain(129, 1.0f);
    const std::vector<GoalGroup> goals = {{"spot", Region::disc({64.0f, 64.0f}, 4.0f), ArrivalPolicy::Stay}};
    const SpawnPattern spawn{Region::rect({10.0f, 10.0f}, {118.0f, 118.0f}), 40, 9, 0};
    auto crowd = makeCrowd(*ground, testSettings(), goals, {spawn});
    ASSERT_TRUE(crowd);
    float worstStuck = 0.0f;
    const std::vector<float> arrived = arrivalTimes(*crowd, 120.0f, &worstStuck);
    const size_t made = size_t(std::count_if(arrived.begin(), arrived.end(), [](float t) { return t >= 0.0f; }));
    EXPECT_EQ(made, arrived.size());
    EXPECT_EQ(crowd->stats().staying, arrived.size());
    EXPECT_EQ(crowd->measureOverlap().pairs, 0u);
}

TEST(CrowdProgress, WanderingAgentsKeepTakingNewGoals) {
    auto ground = flatTerrain(129, 1.0f);
    std::vector<GoalGroup> goals = {{"a", Region::disc({30.0f, 30.0f}, 8.0f)},
                                    {"b", Region::disc({100.0f, 30.0f}, 8.0f)},
                                    {"c", Region::disc({64.0f, 100.0f}, 8.0f)}};
    auto crowd = makeCrowd(*ground, testSettings(), goals, {{Region::disc({64.0f, 55.0f}, 10.0f), 60, 2}});
    ASSERT_TRUE(crowd);
    for (int s = 0; s < int(300.0f / crowd->settings().timeStep); ++s) crowd->step();
    // Each agent walks ~70 m between goals at ~1.3 m/s: several arrivals each.
    EXPECT_GE(crowd->stats().arrivals, 3u * 60u);
    EXPECT_EQ(crowd->stats().staying, 0u);
}

} // namespace
} // namespace tessera::crowd::test
