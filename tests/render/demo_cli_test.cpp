// Bad input gets a clear error, a non-zero exit and never a crash.
#include "DemoProcess.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace tessera::test;

namespace {

void expectCleanFailure(const std::vector<std::string>& args, const std::string& expected) {
    auto run = runDemo(args);
    EXPECT_GT(run.exitCode, 0) << "crashed or succeeded: " << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos) << "expected \"" << expected << "\" in: " << run.output;
}

/// A bad command-line value: exit code 2 (usage error) and a message naming the flag.
void expectUsageError(const std::vector<std::string>& args, const std::string& expected) {
    auto run = runDemo(args);
    EXPECT_EQ(run.exitCode, 2) << args.front() << ": crashed or wrong exit code: " << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos) << "expected \"" << expected << "\" in: " << run.output;
}

} // namespace

TEST(DemoCli, UnknownBackendNamesTheAvailableOnes) {
    // The terrain scene: the crowd scene would solve its fields over 8 km
    // before the backend is looked up.
    auto run = runDemo({"--backend", "nope", "--scene", "terrain"});
    EXPECT_GT(run.exitCode, 0) << run.output;
    for (const char* name : {"unknown backend \"nope\"", "hulldomain", "meshshader", "null", "r2vb", "streamout"})
        EXPECT_NE(run.output.find(name), std::string::npos) << name << " missing from: " << run.output;
}

TEST(DemoCli, BadFlagsFailClearly) {
    expectCleanFailure({"--frobnicate"}, "unknown option \"--frobnicate\"");
    expectCleanFailure({"--frames"}, "--frames needs a value");
    expectCleanFailure({"--frames", "many"}, "--frames expects a whole number");
    // One syntax for every program (tessera::cli): --flag=value reads the same.
    expectCleanFailure({"--frames=many"}, "--frames expects a whole number");
    expectCleanFailure({"--window=yes"}, "--window takes no value");
    expectCleanFailure({"--backend", "null", "stray"}, "unexpected argument \"stray\"");
    expectCleanFailure({"--width", "0"}, "--width expects a whole number from 16");
    expectCleanFailure({"--camera", "1,2"}, "--camera");
    expectCleanFailure({"--clear-color", "1,0"}, "--clear-color expects r,g,b");
    expectCleanFailure({"--clear-color", "2,0,0"}, "--clear-color expects r,g,b");
    expectCleanFailure({"--device", "no-such-gpu", "--backend", "r2vb", "--scene", "terrain"}, "--device no-such-gpu");
}

TEST(DemoCli, BadTerrainFlagsFailClearly) {
    expectUsageError({"--terrain-mode", "bogus"},
                     "--terrain-mode expects lowres, continuous or adaptive, got \"bogus\"");
    expectUsageError({"--terrain-mode"}, "--terrain-mode needs a value");
    expectUsageError({"--tess-metric", "bogus"}, "--tess-metric expects screen, distance, silhouette or detail");
    expectUsageError({"--tess-target", "0"}, "--tess-target expects a number");
    expectUsageError({"--tess-level", "abc"}, "--tess-level expects a number from 1 to 64, got \"abc\"");
    expectUsageError({"--tess-max", "80"}, "--tess-max expects a number from 1 to 64");
    expectUsageError({"--tess-distance", "0"}, "--tess-distance expects a number");
    expectUsageError({"--splat", "1,2"}, "--splat expects x,z,radius[,depth]");
    expectUsageError({"--splat", "1,2,-5"}, "--splat expects x,z,radius[,depth]");
    expectUsageError({"--splat", "1,2,3,-1"}, "--splat expects x,z,radius[,depth]");
    expectUsageError({"--splat", "a,b,c"}, "--splat expects x,z,radius[,depth]");
    expectUsageError({"--bench", "foo"}, "--bench expects terrain, characters, crowd, crowd-sim or subdiv, got \"foo\"");
    expectUsageError({"--meteors", "-1"}, "--meteors expects a whole number");
    expectUsageError({"--device-memory-cap", "0"}, "--device-memory-cap expects a whole number from 1");
    expectUsageError({"--device-memory-cap", "lots"}, "--device-memory-cap expects a whole number");
}

TEST(DemoCli, ShadowsFlagIsCheckedAgainstTheBackend) {
    expectUsageError({"--shadows", "soft"}, "--shadows expects auto, blob, cascaded or none");
    // Blob shadows are every backend's; cascaded ones only where drawn
    // (every GPU backend; the null backend draws nothing).
    expectCleanFailure({"--shadows", "cascaded", "--backend", "null", "--scene", "terrain", "--frames", "1"},
                       "--shadows cascaded: backend null draws no cascaded shadow maps");
    auto run = runDemo({"--shadows", "blob", "--backend", "r2vb", "--scene", "terrain", "--frames", "1", "--width",
                        "64", "--height", "36"});
    EXPECT_EQ(run.exitCode, 0) << run.output;
}

TEST(DemoCli, BadHeightMapNamesTheFile) {
    const std::string bogus = std::string(TESSERA_TEST_OUTPUT_DIR) + "/not_a_png.png";
    std::ofstream(bogus) << "definitely not a PNG";
    expectCleanFailure({"--backend", "null", "--heightmap", bogus}, "not_a_png.png");
    expectCleanFailure({"--backend", "null", "--heightmap", "/nonexistent/h.png"}, "/nonexistent/h.png");
}

TEST(DemoCli, ScreenshotToUnwritablePathFailsClearly) {
    expectCleanFailure({"--backend", "r2vb", "--scene", "terrain", "--frames", "1", "--width", "64", "--height", "64",
                        "--screenshot", "/proc/forbidden/shot.png"},
                       "/proc/forbidden/shot.png");
}

TEST(DemoCli, ListBackendsShowsCapabilitiesOnTheDevice) {
    auto run = runDemo({"--list-backends"});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (const char* text : {"device:", "hulldomain", "hardware", "64.00", "streamout", "emulated", "14.99", "r2vb", "null"})
        EXPECT_NE(run.output.find(text), std::string::npos) << text << " missing from: " << run.output;
}

TEST(DemoCli, ListDevicesShowsLavapipeOrAGpu) {
    auto run = runDemo({"--list-devices"});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("0: "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("[default]"), std::string::npos) << run.output;
}

TEST(DemoCli, HelpExitsZero) {
    auto run = runDemo({"--help"});
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_NE(run.output.find("--backend"), std::string::npos);
}
