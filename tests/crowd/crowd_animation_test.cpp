// Animation state: walk or idle from speed, the walk phase following the
// ground covered so feet do not slide.

#include "CrowdTestWorld.h"

#include <cmath>

namespace tessera::crowd::test {
namespace {

TEST(CrowdAnimation, WalkPhaseFollowsTheGroundCovered) {
    auto ground = flatTerrain(257, 1.0f);
    CrowdSettings settings = testSettings();
    settings.walkStrideLength = 1.3f;
    settings.strideRadius = 0.4f;
    // Agents far apart walking a long way: nobody in anybody's way.
    SpawnPattern spawn{Region::rect({20.0f, 20.0f}, {40.0f, 236.0f}), 30, 6, 0, 0.3f, 0.5f};
    auto crowd = makeCrowd(*ground, settings, {{"east", Region::rect({230.0f, 0.0f}, {256.0f, 256.0f})}}, {spawn});
    ASSERT_TRUE(crowd);
    const CrowdAgents& a = crowd->agents();
    for (int s = 0; s < 60; ++s) crowd->step(); // get going
    // Per agent id (indices change as the crowd re-sorts itself).
    std::vector<glm::vec2> from(a.size());
    std::vector<double> cycles(a.size(), 0.0);
    std::vector<float> phase(a.size());
    for (size_t i = 0; i < a.size(); ++i) from[a.id[i]] = xz(a.position[i]), phase[a.id[i]] = a.phase[i];
    for (int s = 0; s < 150; ++s) {
        crowd->step();
        for (size_t i = 0; i < a.size(); ++i) {
            const uint32_t id = a.id[i];
            ASSERT_EQ(a.clip[i], AgentClip::Walk) << "agent " << id;
            ASSERT_GE(a.phase[i], 0.0f);
            ASSERT_LT(a.phase[i], 1.0f);
            float advance = a.phase[i] - phase[id];
            if (advance < 0.0f) advance += 1.0f;
            cycles[id] += advance;
            phase[id] = a.phase[i];
        }
    }
    // Cycles times this agent's stride is the distance walked.
    for (size_t i = 0; i < a.size(); ++i) {
        const uint32_t id = a.id[i];
        const float stride = settings.walkStrideLength * a.radius[i] / settings.strideRadius;
        const float walked = glm::distance(from[id], xz(a.position[i]));
        EXPECT_NEAR(float(cycles[id]) * stride, walked, 0.02f * walked) << "agent " << id;
    }
}

TEST(CrowdAnimation, StandingAgentsIdleAndArrivalsStop) {
    auto ground = flatTerrain(129, 1.0f);
    CrowdSettings settings = testSettings();
    // The goal covers the spawn: everybody has arrived at once and stays.
    auto crowd = makeCrowd(*ground, settings, {{"here", Region::disc({64.0f, 64.0f}, 30.0f), ArrivalPolicy::Stay}},
                           {{Region::disc({64.0f, 64.0f}, 10.0f), 20, 1}});
    ASSERT_TRUE(crowd);
    for (int s = 0; s < int(20.0f / settings.timeStep); ++s) crowd->step();
    const CrowdAgents& a = crowd->agents();
    EXPECT_EQ(crowd->stats().staying, a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.clip[i], AgentClip::Idle) << "agent " << i;
        EXPECT_LT(glm::length(a.velocity[i]), settings.idleBelow);
    }
}

} // namespace
} // namespace tessera::crowd::test
