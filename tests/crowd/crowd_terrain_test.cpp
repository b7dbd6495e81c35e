// Terrain following: agents stand on the ground, never on slopes too steep
// to walk, and walk slower uphill.

#include "CrowdTestWorld.h"

#include <cmath>

namespace tessera::crowd::test {
namespace {

// Rolling hills with a few steep cones: much of it walkable, some not.
std::unique_ptr<terrain::Terrain> hills() {
    return makeTerrain(257, 1.0f, [](float x, float z) {
        float h = 30.0f + 13.0f * std::sin(x * 0.05f) * std::cos(z * 0.04f);
        for (glm::vec2 peak : {glm::vec2(80.0f, 90.0f), glm::vec2(170.0f, 150.0f), glm::vec2(120.0f, 200.0f)})
            h += std::max(0.0f, 40.0f - 1.6f * glm::distance(glm::vec2(x, z), peak));
        return h;
    });
}

TEST(CrowdTerrain, AgentsStandOnTheGroundAndNeverOnTooSteepASlope) {
    auto ground = hills();
    const CrowdSettings settings = testSettings();
    const std::vector<GoalGroup> goals = {{"a", Region::disc({30.0f, 30.0f}, 12.0f)},
                                          {"b", Region::disc({225.0f, 225.0f}, 12.0f)},
                                          {"c", Region::disc({225.0f, 30.0f}, 12.0f)}};
    auto crowd = makeCrowd(*ground, settings, goals, {{Region::disc({128.0f, 128.0f}, 40.0f), 200, 4}});
    ASSERT_TRUE(crowd);
    const float limit = std::tan(glm::radians(settings.maxSlopeDegrees));
    float steepest = 0.0f;
    for (int s = 0; s < int(60.0f / settings.timeStep); ++s) {
        crowd->step();
        const CrowdAgents& a = crowd->agents();
        for (size_t i = 0; i < a.size(); ++i) {
            const glm::vec3 p = a.position[i];
            ASSERT_EQ(p.y, ground->heightAt(p.x, p.z)) << "agent " << i << " is not on the ground";
            const glm::vec3 n = ground->normalAt(p.x, p.z);
            const float slope = std::sqrt(n.x * n.x + n.z * n.z) / n.y;
            steepest = std::max(steepest, slope);
            ASSERT_LE(slope, limit) << "agent " << i << " on a slope of " << glm::degrees(std::atan(slope)) << " degrees";
        }
    }
    EXPECT_GT(steepest, 0.5f * limit) << "the hills should have tested the limit";
}

TEST(CrowdTerrain, SteepGroundIsSlowerToWalk) {
    // One field through a uniform 25 degree slope, one on the flat.
    const float grade = std::tan(glm::radians(25.0f));
    auto slope = makeTerrain(129, 1.0f, [=](float x, float) { return 10.0f + grade * x; });
    auto flat = flatTerrain(129, 1.0f);
    const GoalGroup goal{"top", Region::rect({110.0f, 0.0f}, {128.0f, 128.0f})};
    auto up = makeCrowd(*slope, testSettings(), {goal}, {});
    auto level = makeCrowd(*flat, testSettings(), {goal}, {});
    ASSERT_TRUE(up && level);
    // Speed falls off quadratically to slopeSpeedAtLimit at the limit;
    // cost per metre is its inverse.
    const CrowdSettings s = testSettings();
    const glm::vec2 start(20.0f, 64.0f);
    const float ratio = up->field(0).sample(start) / level->field(0).sample(start);
    const float t = grade / std::tan(glm::radians(s.maxSlopeDegrees));
    EXPECT_NEAR(ratio, 1.0f / (1.0f - (1.0f - s.slopeSpeedAtLimit) * t * t), 0.05f);
}

} // namespace
} // namespace tessera::crowd::test
