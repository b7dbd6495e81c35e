// The crowd scene (--scene crowd): the crowd simulation's agents drawn as the
// generated creatures on every GPU backend under the validation layer,
// meteors landing among them on the null backend over the content terrain,
// and the --agents errors. Most runs use a 2 km crop of the content terrain,
// so creating the crowd takes a fraction of a second.
#include "CharacterDemo.h"
#include "CharacterHoles.h"
#include "CrowdDemo.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

using namespace tessera::test;

// Each GPU backend draws the nearest agents as creatures: alone on magenta,
// so every pixel that is not magenta is a creature's.
TEST(CrowdDemoScene, CreaturesDrawnOnEveryGpuBackend) {
    const std::string terrain = smallCrowdTerrain();
    for (const char* backend : {"hulldomain", "r2vb", "streamout", "meshshader"}) {
        SCOPED_TRACE(backend);
        if (!deviceRunsBackend(backend)) continue;
        const std::vector<std::string> args = {
            "--scene", "crowd", "--backend", backend, "--heightmap",  terrain,         "--frames", "3",
            "--width", "320",   "--height",  "180",   "--no-terrain", "--clear-color", "1,0,1",
            "--look",  "plain"}; // the clear colour as background, not the sky
        const DemoShot shot = runDemoShot(args, testOutputDir("crowd") / ("crowd_" + std::string(backend) + ".png"));
        ASSERT_EQ(shot.result.exitCode, 0) << shot.command << "\n" << shot.result.output;
        EXPECT_TRUE(validationClean(shot.result)) << shot.command << "\n" << shot.result.output;
        EXPECT_NE(shot.result.output.find("crowd: 2000 agents on "), std::string::npos) << shot.result.output;
        // Every GPU backend culls and bins the whole crowd on the GPU.
        const std::string mode = "every agent drawn instanced, culled and sorted into LOD tiers on the GPU";
        EXPECT_NE(shot.result.output.find(mode), std::string::npos) << shot.result.output;
        ASSERT_TRUE(shot.image) << shot.readError;
        const size_t drawn = size_t(320) * 180 - findHoles(*shot.image).magenta;
        std::cout << "[crowd] " << backend << ": creatures cover " << drawn << " px of 320x180\n";
        EXPECT_GT(drawn, 300u) << "no creatures drawn: " << shot.command;
    }
}

// The real scene's defaults (2000 agents on the 8 km content terrain) on the
// null backend, with three craters landing among the agents: they flee.
TEST(CrowdDemoScene, MeteorsLandAmongTheAgentsOnTheNullBackend) {
    const std::vector<std::string> args = {"--scene", "crowd", "--backend", "null", "--meteors", "3", "--frames", "60"};
    const ProcessResult run = runDemo(args);
    ASSERT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
    EXPECT_NE(run.output.find("3 meteor impacts landed"), std::string::npos) << run.output;
    EXPECT_EQ(crowdFigure(run.output, "steps").value_or(-1), 60) << run.output;
    EXPECT_GT(crowdFigure(run.output, "fleeing").value_or(-1), 0) << "nobody fled the craters:\n" << run.output;
    EXPECT_GT(crowdFigure(run.output, "walking").value_or(-1), 0) << run.output;
}

TEST(CrowdDemoScene, BadAgentCountsFailWithOneLine) {
    for (const char* count : {"0", "x", "-5", "999999999999", "10,20"})
        expectOneLineError({"--scene", "crowd", "--backend", "null", "--agents", count}, 2, "--agents");
    expectOneLineError({"--scene", "crowd", "--crowd-draw", "many"}, 2, "--crowd-draw");
    expectOneLineError({"--scene", "terrain", "--agents", "100"}, 2, "--agents is for --scene crowd");
    // A million agents fit in memory but not on 2 km of terrain: the layout's
    // own error, as it is.
    expectOneLineError({"--agents", "1000000", "--backend", "null", "--heightmap", smallCrowdTerrain()}, 1,
                       "crowd layout:");
}

// --model files join the crowd when they can walk; one that cannot is one
// line naming the file and why (no animation clip; a clip that covers no
// ground, as a rigid, node-animated box or a bending cylinder's), and too many
// creatures for one crowd is refused.
TEST(CrowdDemoScene, ModelsJoinTheCrowdOrFailClearly) {
    const std::string terrain = smallCrowdTerrain();
    const auto model = [](const std::string& relative) { return (sharedTestdataDir() / "gltf" / relative).string(); };
    const std::vector<std::string> walker = {"--scene", "crowd", "--backend", "null", "--heightmap", terrain,
                                             "--agents", "200",  "--frames",  "2",    "--model",
                                             model("CesiumMan/glTF-Binary/CesiumMan.glb")};
    const ProcessResult ok = runDemo(walker);
    EXPECT_EQ(ok.exitCode, 0) << demoCommandLine(walker) << "\n" << ok.output;
    EXPECT_NE(ok.output.find("CesiumMan.glb"), std::string::npos) << "the gait line names every creature: " << ok.output;

    const std::vector<std::string> base = {"--scene", "crowd", "--backend", "null", "--heightmap", terrain,
                                           "--agents", "200", "--frames", "1"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = base;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    expectOneLineError(with({"--model", model("Box/glTF-Binary/Box.glb")}), 1, "Box.glb: has no animation clip");
    expectOneLineError(with({"--model", model("BoxAnimated/glTF-Binary/BoxAnimated.glb")}), 1,
                       "BoxAnimated.glb: its walk clip covers no ground");
    expectOneLineError(with({"--model", model("RiggedSimple/glTF-Binary/RiggedSimple.glb")}), 1,
                       "RiggedSimple.glb: its walk clip covers no ground");
    expectOneLineError(with({"--model", "/nonexistent/walker.glb"}), 1, "/nonexistent/walker.glb");
    std::vector<std::string> many;
    for (int i = 0; i < 6; ++i) many.insert(many.end(), {"--model", model("CesiumMan/glTF-Binary/CesiumMan.glb")});
    expectOneLineError(with(many), 1, "a crowd mixes at most 8 creatures");
}
