// The characters scene from the command line: --model with files the engine
// cannot use (missing, invalid glTF from the Khronos validator's suite, Draco
// test files) fails with one line naming the file and never crashes; bad
// character flags fail clearly; CesiumMan renders in its binary and Draco
// variants under the validation layer.
#include "CharacterDemo.h"
#include "CharacterHoles.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

using namespace tessera;
using namespace tessera::test;

namespace {

std::string testdata(const std::string& relative) {
    return (sharedTestdataDir() / relative).string();
}

/// The demo loading only `model` (no crowd, no terrain drawn) on r2vb.
std::vector<std::string> modelArgs(const std::string& model) {
    return {"--backend", "r2vb", "--crowd", "0",  "--model",  model, "--no-terrain",
            "--frames",  "1",    "--width", "64", "--height", "64",  "--validation"};
}

/// A file the engine cannot use: a non-zero exit (not a crash: runDemo gives
/// -1 then) and exactly one error line, which names the file.
void expectRejected(const std::string& model) {
    SCOPED_TRACE(model);
    const auto args = modelArgs(model);
    const auto run = runDemo(args);
    EXPECT_GT(run.exitCode, 0) << "crashed (-1) or succeeded (0): " << demoCommandLine(args) << "\n" << run.output;
    const auto errors = errorLines(run.output);
    ASSERT_EQ(errors.size(), 1u) << demoCommandLine(args) << "\n" << run.output;
    EXPECT_NE(errors.front().find(model), std::string::npos) << "the error does not name the file: " << errors.front();
    std::cout << "[cli] " << errors.front() << "\n";
}

} // namespace

TEST(CharacterCli, MissingModelNamesTheFile) {
    expectRejected("/nonexistent.glb");
}

// Invalid files whose expected validator report has errors: a bad GLB magic,
// JSON that does not parse, and a skin naming a joint node that does not
// exist.
TEST(CharacterCli, InvalidGltfNamesTheFileAndNeverCrashes) {
    for (const char* file :
         {"bad/gltf-validator/base/data/glb/invalid_magic.glb", "bad/gltf-validator/base/data/json/invalid_syntax.gltf",
          "bad/gltf-validator/base/data/skin/unresolved_joint.gltf"})
        expectRejected(testdata(file));
}

// Draco's own glTF test files: each either renders cleanly or fails with one
// line naming the file; none crashes.
TEST(CharacterCli, DracoTestFilesRenderOrFailCleanly) {
    for (const char* file : {"bad/draco/Box/glTF_Binary/Box_Draco.glb", "bad/draco/simple_skin.gltf",
                             "bad/draco/ZeroLengthBufferView/ZeroLengthBufferView.gltf"}) {
        const std::string model = testdata(file);
        SCOPED_TRACE(model);
        const auto args = modelArgs(model);
        const auto run = runDemo(args);
        ASSERT_NE(run.exitCode, -1) << "crashed: " << demoCommandLine(args) << "\n" << run.output;
        if (run.exitCode == 0) {
            EXPECT_TRUE(validationClean(run)) << demoCommandLine(args) << "\n" << run.output;
            std::cout << "[cli] " << file << ": renders\n";
            continue;
        }
        const auto errors = errorLines(run.output);
        ASSERT_EQ(errors.size(), 1u) << demoCommandLine(args) << "\n" << run.output;
        EXPECT_NE(errors.front().find(model), std::string::npos) << errors.front();
        std::cout << "[cli] " << file << ": rejected: " << errors.front() << "\n";
    }
}

TEST(CharacterCli, BadCharacterFlagsFailClearly) {
    auto bogus = runDemo({"--scene", "characters", "--character-path", "bogus"});
    EXPECT_EQ(bogus.exitCode, 2) << bogus.output;
    EXPECT_NE(bogus.output.find("--character-path expects two-pass or single-pass, got \"bogus\""), std::string::npos)
        << bogus.output;

    // Level 20 parses (hulldomain goes to 64) but the emulated tessellator
    // stops at 14.99: the demo refuses it rather than clamping silently.
    std::vector<std::string> args = modelArgs(froblinFile(1));
    args.insert(args.end(), {"--character-level", "20"});
    const auto tooHigh = runDemo(args);
    EXPECT_GT(tooHigh.exitCode, 0) << demoCommandLine(args) << "\n" << tooHigh.output;
    const auto errors = errorLines(tooHigh.output);
    ASSERT_EQ(errors.size(), 1u) << tooHigh.output;
    for (const char* text : {"--character-level 20", "r2vb", "tessellates up to level 14.99"})
        EXPECT_NE(errors.front().find(text), std::string::npos) << text << " missing from: " << errors.front();
}

// CesiumMan as a user would place it: the glTF-Binary and the Draco variant,
// on the characters scene's own terrain, then alone on magenta to see that
// it is drawn at all.
TEST(CharacterCli, CesiumManBinaryAndDracoRender) {
    for (const char* variant : {"glTF-Binary/CesiumMan.glb", "glTF-Draco/CesiumMan.gltf"}) {
        const std::string model = testdata(std::string("gltf/CesiumMan/") + variant);
        SCOPED_TRACE(model);
        const std::vector<std::string> args = {"--scene",  "characters", "--crowd",     "0",       "--model",
                                               model,      "--frames",   "2",           "--width", "160",
                                               "--height", "120",        "--validation"};
        const auto run = runDemo(args);
        EXPECT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
        EXPECT_TRUE(validationClean(run)) << demoCommandLine(args) << "\n" << run.output;

        const std::string name = std::string(variant).substr(0, std::string(variant).find('/'));
        std::vector<std::string> alone = soloCharacterArgs("hulldomain", model, "1,0,1", "3", 160, 120);
        alone.insert(alone.end(), {"--frames", "1"});
        const DemoShot shot = runDemoShot(alone, testOutputDir("character_cli") / ("cesiumman_" + name + ".png"));
        ASSERT_EQ(shot.result.exitCode, 0) << shot.command << "\n" << shot.result.output;
        EXPECT_TRUE(validationClean(shot.result)) << shot.command << "\n" << shot.result.output;
        ASSERT_TRUE(shot.image) << shot.readError;
        const size_t drawn = size_t(160) * 120 - findHoles(*shot.image).magenta;
        std::cout << "[cli] CesiumMan " << name << " alone covers " << drawn << " px of 160x120\n";
        EXPECT_GT(drawn, 200u) << "CesiumMan is not drawn: " << shot.command;
    }
}
