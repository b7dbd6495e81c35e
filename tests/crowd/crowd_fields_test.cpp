// Potential fields: the eikonal solve against analytic distances, walls, and
// how terrain changes reach the fields.

#include "CrowdTestWorld.h"

#include <cmath>

namespace tessera::crowd::test {
namespace {

TEST(CrowdFields, FlatGroundGivesTheEuclideanDistanceToTheGoal) {
    // No agents: the crowd is just its fields (zero agents is a valid crowd).
    auto ground = flatTerrain(257, 1.0f);
    const Region goal = Region::disc({60.0f, 80.0f}, 6.0f);
    auto crowd = makeCrowd(*ground, testSettings(), {{"goal", goal}}, {});
    ASSERT_TRUE(crowd);
    const NavGrid& grid = crowd->navGrid();
    const PotentialField& field = crowd->field(0);
    float worst = 0.0f;
    for (uint32_t j = 0; j < grid.height(); ++j)
        for (uint32_t i = 0; i < grid.width(); ++i) {
            const glm::vec2 c = grid.cellCenter(i, j);
            const float exact = std::max(0.0f, glm::distance(c, goal.center) - goal.halfSize.x);
            worst = std::max(worst, std::abs(field.at(grid.index(i, j)) - exact));
        }
    // Upwind schemes err most on curved fronts between the stencil's
    // directions, growing slowly with distance: within one cell everywhere,
    // 200 cells away, is the bar.
    EXPECT_LE(worst, grid.cellSize()) << "largest error " << worst << " m";
    EXPECT_EQ(crowd->agents().size(), 0u);
    crowd->step(); // and a crowd of nobody steps
    EXPECT_EQ(crowd->stats().agents, 0u);
}

TEST(CrowdFields, AnImpassableRidgeIsWalkedAroundNeverCrossed) {
    // A ridge across the map along x = 100 with one gap near z = 30; goal
    // and crowd on opposite sides, the straight line blocked.
    auto ground = wallTerrain(201, 1.0f, 100.0f, [](float z) { return z > 25.0f && z < 35.0f; });
    const std::vector<GoalGroup> goals = {{"east", Region::disc({160.0f, 150.0f}, 10.0f), ArrivalPolicy::Stay}};
    const std::vector<SpawnPattern> spawns = {{Region::disc({40.0f, 150.0f}, 12.0f), 60, 3, 0}};
    auto crowd = makeCrowd(*ground, testSettings(), goals, spawns);
    ASSERT_TRUE(crowd);
    // The field goes round: well above the straight-line distance.
    const float straight = glm::distance(glm::vec2(40.0f, 150.0f), glm::vec2(160.0f, 150.0f)) - 10.0f;
    const float viaGap = glm::distance(glm::vec2(40.0f, 150.0f), glm::vec2(100.0f, 30.0f)) +
                         glm::distance(glm::vec2(100.0f, 30.0f), glm::vec2(160.0f, 150.0f)) - 10.0f;
    const float potential = crowd->field(0).sample({40.0f, 150.0f});
    EXPECT_GT(potential, straight + 50.0f);
    EXPECT_NEAR(potential, viaGap, 0.08f * viaGap);
    // Nobody ever stands on the ridge, and nobody gets to the other side
    // except through the gap.
    const uint32_t steps = uint32_t(320.0f / crowd->settings().timeStep);
    std::vector<float> lastX(crowd->agents().size()); // by agent id
    for (size_t a = 0; a < lastX.size(); ++a) lastX[crowd->agents().id[a]] = crowd->agents().position[a].x;
    for (uint32_t s = 0; s < steps; ++s) {
        crowd->step();
        const CrowdAgents& agents = crowd->agents();
        for (size_t a = 0; a < agents.size(); ++a) {
            const glm::vec2 p = xz(agents.position[a]);
            ASSERT_TRUE(crowd->passable(p)) << "agent " << a << " on impassable ground at " << p.x << ", " << p.y;
            const uint32_t id = agents.id[a];
            if ((lastX[id] < 100.0f) != (p.x < 100.0f)) {
                ASSERT_TRUE(p.y > 25.0f && p.y < 35.0f) << "agent " << id << " crossed the ridge at z = " << p.y;
            }
            lastX[id] = p.x;
        }
    }
    EXPECT_EQ(crowd->stats().staying, crowd->agents().size()) << "everybody went round and arrived";
}

TEST(CrowdFields, ACraterIsReSolvedLocallyWithinTheBudget) {
    auto ground = flatTerrain(257, 1.0f);
    CrowdSettings settings = testSettings();
    settings.fieldTileBudget = 32;
    auto crowd = makeCrowd(*ground, settings, {{"goal", Region::disc({30.0f, 128.0f}, 8.0f)}}, {});
    ASSERT_TRUE(crowd);
    crowd->step();
    EXPECT_EQ(crowd->stats().fieldTilesWaiting, 0u);
    // A crater between the goal and the far side: the field must go round it.
    ground->splat(glm::vec2(90.0f, 128.0f), 20.0f);
    uint32_t steps = 0;
    do {
        crowd->step();
        ++steps;
        EXPECT_LE(crowd->stats().fieldTilesSolved, settings.fieldTileBudget);
    } while (crowd->stats().fieldTilesWaiting > 0 && steps < 1000);
    EXPECT_LT(steps, 1000u) << "the fields never settled";
    const PotentialField& field = crowd->field(0);
    // Behind the crater, the way round is longer than the way through was.
    const float behind = field.sample({150.0f, 128.0f});
    EXPECT_GT(behind, 150.0f - 30.0f - 8.0f + 5.0f);
    EXPECT_FALSE(field.reachable({90.0f, 128.0f})) << "a fresh crater is impassable";
    // Far from the crater nothing changed.
    EXPECT_NEAR(field.sample({30.0f, 40.0f}), 88.0f - 8.0f, 1.0f);
}

} // namespace
} // namespace tessera::crowd::test
