// The crowd as one scene object: its bounds hierarchy, culling, memory and
// the automatic layout for terrains nobody laid out.

#include "CrowdTestWorld.h"
#include "tessera/crowd/CrowdLayout.h"
#include "tessera/scene/Camera.h"
#include "tessera/scene/SceneGraph.h"

#include <algorithm>

namespace tessera::crowd::test {
namespace {

std::unique_ptr<Crowd> wanderers(terrain::Terrain& ground, uint32_t count) {
    const std::vector<GoalGroup> goals = {{"a", Region::disc({60.0f, 60.0f}, 15.0f)},
                                          {"b", Region::disc({450.0f, 450.0f}, 15.0f)},
                                          {"c", Region::disc({60.0f, 450.0f}, 15.0f)}};
    return makeCrowd(ground, testSettings(), goals, {{Region::disc({256.0f, 256.0f}, 60.0f), count, 3}});
}

TEST(CrowdScene, OneSceneNodeWhoseBoundsFollowTheAgents) {
    auto ground = flatTerrain(513, 1.0f);
    auto crowd = wanderers(*ground, 2000);
    ASSERT_TRUE(crowd);
    scene::SceneGraph graph;
    const scene::NodeId root = graph.createNode("world");
    const scene::NodeId node = crowd->attach(graph, root, 7);
    EXPECT_EQ(graph.nodeCount(), 2u) << "one node for the whole crowd, not one per agent";
    for (int s = 0; s < 90; ++s) crowd->step();
    graph.updateTransforms();
    const scene::Aabb box = graph.node(node).worldBounds;
    EXPECT_EQ(graph.node(node).kind, 7u);
    const CrowdAgents& a = crowd->agents();
    for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_TRUE(box.contains(a.position[i])) << "agent " << a.id[i];
        // Re-sorted in memory twice by now; ids still find their agents.
        ASSERT_EQ(crowd->indexOf(a.id[i]), i);
    }
    crowd.reset();
    EXPECT_FALSE(graph.isAlive(node)) << "a crowd takes its node with it";
}

TEST(CrowdScene, CullingKeepsEveryAgentInView) {
    auto ground = flatTerrain(513, 1.0f);
    auto crowd = wanderers(*ground, 3000);
    ASSERT_TRUE(crowd);
    for (int s = 0; s < 120; ++s) crowd->step();
    scene::Camera camera;
    camera.setAspect(16.0f / 9.0f);
    const CrowdAgents& a = crowd->agents();
    size_t fewest = a.size();
    // From inside the crowd looking two ways along the ground, and from
    // high above looking down on all of it.
    for (glm::vec4 pose : {glm::vec4(256.0f, 12.0f, 256.0f, 0.0f), glm::vec4(256.0f, 12.0f, 256.0f, 2.0f),
                           glm::vec4(256.0f, 300.0f, 256.0f, 0.5f)}) {
        scene::CameraPose p;
        p.position = glm::vec3(pose);
        p.yaw = pose.w;
        p.pitch = pose.y > 100.0f ? -1.5f : -0.1f;
        camera.setPose(p);
        const scene::Frustum frustum = camera.frustum();
        std::vector<uint32_t> culled;
        crowd->cull(frustum, culled);
        std::sort(culled.begin(), culled.end());
        EXPECT_TRUE(std::adjacent_find(culled.begin(), culled.end()) == culled.end()) << "each agent once";
        size_t visible = 0;
        for (size_t i = 0; i < a.size(); ++i) {
            const float r = a.radius[i];
            const scene::Aabb box{a.position[i] - glm::vec3(r, 0.0f, r), a.position[i] + glm::vec3(r, 2.0f, r)};
            if (!frustum.intersects(box)) continue;
            ++visible;
            ASSERT_TRUE(std::binary_search(culled.begin(), culled.end(), uint32_t(i))) << "agent " << i << " culled";
        }
        EXPECT_GE(culled.size(), visible);
        fewest = std::min(fewest, culled.size());
    }
    EXPECT_LT(fewest, a.size() / 2) << "the hierarchy should reject what is out of view";
}

TEST(CrowdScene, SimulationStateStaysUnder128BytesPerAgent) {
    auto ground = flatTerrain(513, 1.0f);
    auto crowd = wanderers(*ground, 5000);
    ASSERT_TRUE(crowd);
    crowd->step();
    const CrowdMemory memory = crowd->memory();
    EXPECT_LE(memory.bytesPerAgent, 128.0);
    const CrowdMemory estimate = Crowd::estimateMemory(*ground, testSettings(), 5000, 3);
    EXPECT_LE(memory.bytesPerAgent, estimate.bytesPerAgent * 1.05);
    EXPECT_GT(memory.fieldBytes, 0u);
}

TEST(CrowdScene, LayoutFindsOpenConnectedGround) {
    // Hills around a valley; the layout must put spawn and goals in it.
    auto ground = makeTerrain(257, 2.0f, [](float x, float z) {
        const float d = glm::distance(glm::vec2(x, z), glm::vec2(256.0f, 256.0f));
        return d < 180.0f ? 10.0f : std::min(200.0f, 10.0f + 3.0f * (d - 180.0f));
    });
    const NavGrid grid(*ground, 2.0f, 35.0f, 0.35f);
    CrowdLayoutRequest request;
    request.agents = 3000;
    request.goalDistance = 120.0f;
    auto layout = planCrowdLayout(grid, request);
    ASSERT_TRUE(layout.ok()) << layout.error().message;
    EXPECT_LT(glm::distance(layout.value().spawn.center, glm::vec2(256.0f)), 60.0f);
    ASSERT_EQ(layout.value().goals.size(), 4u);
    for (const GoalGroup& goal : layout.value().goals) EXPECT_TRUE(grid.walkable(goal.region.center));
    CrowdSettings settings = testSettings();
    settings.cellSize = 2.0f;
    auto crowd = makeCrowd(*ground, settings, layout.value().goals, {{layout.value().spawn, 3000, 1}});
    EXPECT_TRUE(crowd);

    request.agents = 2000000;
    auto tooMany = planCrowdLayout(grid, request);
    ASSERT_FALSE(tooMany.ok());
    EXPECT_NE(tooMany.error().message.find("largest walkable area"), std::string::npos);
}

} // namespace
} // namespace tessera::crowd::test
