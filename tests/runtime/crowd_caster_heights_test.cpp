// Every creature of the crowd is drawn the crowd's height and walks its own
// stride: with a model of another build mixed in (CesiumMan among the
// froblins, --model), CesiumMan stands as tall as a froblin (before, the crowd
// scaled every creature to one stride and drew it at a third of their size)
// and walks its own long stride as a kind of walker of its own
// (crowd::WalkerKind). The shadow casters are as tall as the creatures are
// drawn (docs/CROWD.md 6.10, "Shadows").
#include "SceneOptions.h"

#include "tessera/runtime/SceneRun.h"
#include "tessera/runtime/SimulatedCrowd.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace tessera::runtime {
namespace {

TEST(CrowdCasterHeights, EveryCreatureStandsTheCrowdsHeightAndWalksItsOwnStride) {
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
    // One frame, its instances built from the agents as they are now (no
    // step running ahead of the frame): the casters come from the instances.
    crowd->setStepAhead(false);
    ASSERT_TRUE(created.value()->step(0, false));
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
        // keepNearest may reorder: find the agent by its position (the
        // feet stand on the drawn ground, the agent on the height field).
        size_t i = 0;
        while (i < agents.position.size() &&
               (casters[k].x != agents.position[i].x || casters[k].z != agents.position[i].z))
            ++i;
        ASSERT_LT(i, agents.position.size());
        const uint32_t creature = agents.id[i] % creatures;
        const float ratio = casters[k].w / agents.radius[i];
        if (perRadius[creature] == 0.0f) perRadius[creature] = ratio;
        EXPECT_NEAR(ratio, perRadius[creature], 1e-3f * perRadius[creature]) << "creature " << creature;
    }
    // Each creature, CesiumMan too, the crowd's height at the stride radius.
    const crowd::CrowdSettings& settings = crowd->crowd().settings();
    for (uint32_t c = 0; c < creatures; ++c)
        EXPECT_NEAR(perRadius[c], SimulatedCrowd::kCreatureHeight / settings.strideRadius, 1e-3f) << "creature " << c;
    // Each its own stride: one kind of walker per creature, CesiumMan's
    // stride at that size more than twice a froblin's.
    ASSERT_EQ(settings.kinds.size(), creatures);
    for (uint32_t c = 0; c < 3; ++c)
        EXPECT_GT(settings.kinds[3].walkStrideLength, 2.0f * settings.kinds[c].walkStrideLength) << "froblin " << c;
}

} // namespace
} // namespace tessera::runtime
