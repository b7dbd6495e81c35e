// The full look's deferred terrain shading (docs/LOOKS.md, "Deferred terrain
// shading"): the terrain resolve, compute on hulldomain and a fullscreen pass
// on r2vb and streamout, must give the image forward shading gives, keep
// what characters and the wireframe draw, and stay validation-clean.
#include "CharacterDemo.h"
#include "CrowdDemo.h"
#include "ImageCompare.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

// Forward and deferred evaluate the same shading function at the same point
// (the stored distance has 4 mm steps), so they agree to rounding.
constexpr ImageTolerance kSameShading{2, 0.0005, 0.1};
constexpr ImageTolerance kIdentical{0, 0.0, 0.0};

/// Renders `args` twice, forward and deferred, and compares the two.
void expectDeferredMatchesForward(const std::string& name, std::vector<std::string> args,
                                  const ImageTolerance& tolerance = kSameShading) {
    auto shot = [&](const std::string& shading) {
        std::vector<std::string> run = args;
        run.insert(run.end(), {"--terrain-shading", shading});
        return runDemoShot(run, testOutputDir("terrain_resolve") / (name + "_" + shading + ".png"));
    };
    const DemoShot forward = shot("forward");
    const DemoShot deferred = shot("deferred");
    for (const DemoShot* s : {&forward, &deferred}) {
        ASSERT_EQ(s->result.exitCode, 0) << s->command << "\n" << s->result.output;
        EXPECT_TRUE(validationClean(s->result)) << s->command << "\n" << s->result.output;
        ASSERT_TRUE(s->image) << s->readError;
    }
    const auto diff = testOutputDir("terrain_resolve") / (name + ".diff.png");
    const ImageComparison cmp = compareImages(*deferred.image, *forward.image, tolerance, diff.string());
    std::cout << "[terrain resolve] " << name << ": " << cmp.differingFraction * 100.0
              << "% of pixels differ by more than 2/255, mean difference " << cmp.meanDifference << "\n";
    EXPECT_TRUE(cmp.match) << name << ": " << cmp.message << "\n" << deferred.command;
}

class DeferredTerrainShading : public ::testing::TestWithParam<std::string> {};

} // namespace

// The golden view: terrain, sun shadows, detail textures, fog and sky.
TEST_P(DeferredTerrainShading, MatchesForwardShading) {
    if (!deviceRunsBackend(GetParam())) GTEST_SKIP() << "the device cannot run " << GetParam();
    expectDeferredMatchesForward("terrain_" + GetParam(),
                                 {"--scene", "terrain", "--width", "320", "--height", "180", "--frames", "3",
                                  "--camera", "1800,900,6800,-30,-16", "--backend", GetParam()});
}

// Creatures shaded forward over the deferred terrain keep their pixels, and
// their shadows fall on the resolved ground.
TEST_P(DeferredTerrainShading, KeepsTheCrowdShadedForward) {
    if (!deviceRunsBackend(GetParam())) GTEST_SKIP() << "the device cannot run " << GetParam();
    expectDeferredMatchesForward("crowd_" + GetParam(),
                                 {"--scene", "crowd", "--heightmap", smallCrowdTerrain(), "--agents", "300",
                                  "--frames", "3", "--width", "320", "--height", "180", "--backend", GetParam()});
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, DeferredTerrainShading,
                         ::testing::Values("r2vb", "streamout", "hulldomain", "meshshader"),
                         [](const auto& test) { return test.param; });

// The wireframe stays forward (a line's fragments are not on their pixel
// centre's view ray, which the resolve would put them on): asking for
// deferred shading gives the same bytes.
TEST(DeferredTerrainShadingWireframe, StaysForward) {
    for (const char* backend : {"r2vb", "hulldomain"})
        expectDeferredMatchesForward(std::string("wireframe_") + backend,
                                     {"--scene", "terrain", "--width", "320", "--height", "180", "--frames", "2",
                                      "--camera", "1800,900,6800,-30,-16", "--wireframe", "--backend", backend},
                                     kIdentical);
}

TEST(DeferredTerrainShadingFlag, RejectsUnknownValues) {
    expectOneLineError({"--backend", "null", "--terrain-shading", "sideways"}, 2, "--terrain-shading");
}
