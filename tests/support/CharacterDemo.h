#pragma once
/// @file CharacterDemo.h
/// Shared by the character render tests: where the build's generated
/// characters and the shared test data live, and one tessera-demo run under
/// the validation layer that hands back its screenshot.

#include "DemoProcess.h"
#include "TestFiles.h"

#include "tessera/core/ImageFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tessera::test {

/// The build tree's content directory. The render tests have no definition
/// for it, but tessera-demo finds its content in <build>/bin/../content (see
/// game_sample/ContentLocator.cpp), so the tests look where it looks.
inline std::filesystem::path buildContentDir() {
    return (std::filesystem::path(TESSERA_DEMO_EXE).parent_path().parent_path() / "content").lexically_normal();
}

/// A generated creature of the build (tools/creature: froblin_1..3.glb).
inline std::string froblinFile(int seed = 1) {
    return (buildContentDir() / "characters" / ("froblin_" + std::to_string(seed) + ".glb")).string();
}

/// ../shared/testdata beside the checkout (TESSERA_TESTDATA_DIR where a test
/// binary defines it).
inline std::filesystem::path sharedTestdataDir() {
#ifdef TESSERA_TESTDATA_DIR
    return std::filesystem::path(TESSERA_TESTDATA_DIR);
#else
    return (std::filesystem::path(TESSERA_SOURCE_DIR) / ".." / "shared" / "testdata").lexically_normal();
#endif
}

/// The command as a user would type it, for failure messages.
inline std::string demoCommandLine(const std::vector<std::string>& args) {
    std::string text = "tessera-demo";
    for (const auto& a : args) {
        text += ' ';
        text += shellQuote(a);
    }
    return text;
}

/// A failed run of the demo with `args`: exit code `code` and exactly one
/// error line, which names `text`; returns that line (empty on failure).
inline std::string expectOneLineError(const std::vector<std::string>& args, int code, const std::string& text) {
    SCOPED_TRACE(demoCommandLine(args));
    const ProcessResult run = runDemo(args);
    EXPECT_EQ(run.exitCode, code) << run.output;
    const auto errors = errorLines(run.output);
    EXPECT_EQ(errors.size(), 1u) << run.output;
    if (errors.size() != 1u) return {};
    EXPECT_NE(errors.front().find(text), std::string::npos) << errors.front();
    return errors.front();
}

/// True when the demo counted no validation messages (it prints the count
/// last, under --validation).
inline bool validationClean(const ProcessResult& result) {
    return result.output.find("validation messages: 0") != std::string::npos;
}

/// One demo run that ends in a screenshot.
struct DemoShot {
    std::string command;             ///< for messages
    ProcessResult result;            ///< exit code and output
    std::string screenshot;          ///< where the last frame went
    std::optional<Rgba8Image> image; ///< the screenshot, when the run succeeded and it reads back
    std::string readError;           ///< why `image` is empty after a successful run
};

/// Runs the demo with `args` plus --validation and --screenshot `screenshot`
/// (an old file of that name is removed first, so a stale image never passes).
inline DemoShot runDemoShot(std::vector<std::string> args, const std::filesystem::path& screenshot) {
    DemoShot shot;
    shot.screenshot = screenshot.string();
    std::filesystem::remove(screenshot);
    args.insert(args.end(), {"--validation", "--screenshot", shot.screenshot});
    shot.command = demoCommandLine(args);
    shot.result = runDemo(args);
    if (shot.result.exitCode != 0) return shot;
    auto image = readPng(screenshot);
    if (image)
        shot.image = std::move(image.value());
    else
        shot.readError = image.error().message;
    return shot;
}

/// Arguments for one character alone on the clear colour, seen from
/// `orbitDistance` metres at frame 0 of the camera's circle.
inline std::vector<std::string> soloCharacterArgs(const std::string& backend, const std::string& model,
                                                  const std::string& clearColor, const std::string& orbitDistance,
                                                  int width, int height) {
    std::vector<std::string> args = {"--backend", backend, "--crowd", "0", "--model", model, "--no-terrain"};
    // Characters stand on the terrain as the backend would draw it, drawn or
    // not (docs/CROWD.md 6.8); one level cap every backend draws keeps them
    // at the same place on each.
    args.insert(args.end(), {"--tess-max", "14.99"});
    // The plain look: the background stays the clear colour (the full look
    // paints the sky there), so holes show as that colour.
    args.insert(args.end(), {"--clear-color", clearColor, "--look", "plain", "--orbit-distance", orbitDistance});
    args.insert(args.end(), {"--width", std::to_string(width), "--height", std::to_string(height)});
    return args;
}

} // namespace tessera::test
