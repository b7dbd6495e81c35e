// The crowd's shadow casters are as tall as their creatures are drawn: with
// a model of another build mixed in (CesiumMan among the froblins, --model),
// each agent's blob takes its own creature's rest height at the agent's
// scale, not the crowd's mean (docs/CROWD.md 6.10, "Shadows").
#include "SceneOptions.h"

#include "tessera/runtime/SceneRun.h"
#include "tessera/runtime/SimulatedCrowd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

namespace tessera::runtime {
namespace {

TEST(CrowdCasterHeights, EachAgentCastsItsOwnCreaturesHeight) {
    const std::filesystem::path cesiumMan =
        std::filesystem::path(TESSERA_TESTDATA_DIR) / "gltf" / "CesiumMan" / "glTF-Binary" / "CesiumMan.glb";
    if (!std::filesystem::exists(cesiumMan)) GTEST_SKIP() << cesiumMan << " is not there";
    Options options = test::smallSceneOptions("null", "crowd");
    options.heightmap = test::smallTerrain();
    options.models = {cesiumMan.string()};
    options.agents = {200};
    options.meteors = 0;
    auto created = SceneRun::create(options, 1);
    ASSERT_TRUE(created) << created.error().message;
    SimulatedCrowd* crowd = created.value()->world().simulatedCrowd();
    ASSERT_NE(crowd, nullptr);
    const crowd::CrowdAgents& agents = crowd->crowd().agents();
    const uint32_t creatures = uint32_t(crowd->assets().size());
    ASSERT_EQ(creatures, 4u) << "three froblins and CesiumMan";

    // A region holding every agent: one caster per agent, in agent order
    // before keepNearest (which keeps all of them here).
    std::vector<glm::vec4> casters;
    crowd->shadowCasters(glm::vec3(-1e6f, -1e6f, 2e6f), uint32_t(agents.position.size()), casters);
    ASSERT_EQ(casters.size(), agents.position.size());

    // Per creature, height over the agent's radius is one number: the
    // creature's drawn height at the stride radius.
    std::vector<float> perRadius(creatures, 0.0f);
    for (size_t k = 0; k < casters.size(); ++k) {
        // keepNearest may reorder: find the agent by its position.
        size_t i = 0;
        while (i < agents.position.size() && glm::vec3(casters[k]) != agents.position[i]) ++i;
        ASSERT_LT(i, agents.position.size());
        const uint32_t creature = agents.id[i] % creatures;
        const float ratio = casters[k].w / agents.radius[i];
        if (perRadius[creature] == 0.0f) perRadius[creature] = ratio;
        EXPECT_NEAR(ratio, perRadius[creature], 1e-3f * perRadius[creature]) << "creature " << creature;
    }
    const float froblin = *std::max_element(perRadius.begin(), perRadius.begin() + 3);
    EXPECT_GT(perRadius[3], 0.0f);
    // The crowd scales every creature to one stride: CesiumMan, whose stride
    // is long for its height, is drawn much shorter than a froblin, and so
    // is its shadow's caster.
    EXPECT_LT(perRadius[3], 0.6f * froblin);
}

} // namespace
} // namespace tessera::runtime
