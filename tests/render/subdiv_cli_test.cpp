// The subdivision-surface flags and .obj inputs (issue 14): a bad value or a
// bad file gets a clear message naming the flag or the file (and the line),
// a non-zero exit and never a crash; a good shape runs on the null backend.
#include "CharacterDemo.h"
#include "DemoProcess.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace tessera::test;

namespace {

void expectFailure(const std::vector<std::string>& args, int exitCode, const std::string& expected) {
    const ProcessResult run = runDemo(args);
    EXPECT_EQ(run.exitCode, exitCode) << demoCommandLine(args) << ": crashed or wrong exit code: " << run.output;
    EXPECT_NE(run.output.find(expected), std::string::npos)
        << demoCommandLine(args) << ": expected \"" << expected << "\" in: " << run.output;
}

std::string shape(const char* name) {
    return (sharedTestdataDir() / "osd_shapes" / name).string();
}

std::string writeFile(const char* name, const std::string& text) {
    const std::string path = (testOutputDir("subdiv_cli") / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

} // namespace

TEST(SubdivCli, BadFlagsNameTheFlagAndTheValue) {
    expectFailure({"--subdiv-level", "0"}, 2, "--subdiv-level expects a number from 1 to 64, got \"0\"");
    expectFailure({"--subdiv-level", "3:99"}, 2, "--subdiv-level expects a number from 1 to 64, got \"99\"");
    expectFailure({"--subdiv-view", "foo"}, 2, "--subdiv-view expects shaded, patches, levels or mips, got \"foo\"");
    expectFailure({"--normals", "foo"}, 2, "--normals expects accurate or approximate, got \"foo\"");
    expectFailure({"--subdiv-pixels", "0"}, 2, "--subdiv-pixels expects a number from 0.5 to 1000");
    expectFailure({"--subdiv-budget", "-3"}, 2, "--subdiv-budget expects a whole number from 1000");
    expectFailure({"--subdiv-amplitude", "9"}, 2, "--subdiv-amplitude expects a number from 0 to 0.25");
    expectFailure({"--subdiv-level"}, 2, "--subdiv-level needs a value");
    expectFailure({"--scene", "crowd", "--model", shape("catmark_cube.obj")}, 2,
                  "a .obj surface stands in the characters scene");
}

TEST(SubdivCli, BadObjFilesNameTheFileAndTheProblem) {
    const std::vector<std::string> run = {"--backend", "null", "--crowd", "0", "--frames", "1", "--model"};
    auto with = [&](const std::string& file) {
        std::vector<std::string> args = run;
        args.push_back(file);
        return args;
    };
    expectFailure(with("/nonexistent/x.obj"), 1, "/nonexistent/x.obj: no such file");
    const std::string index = writeFile("bad_index.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
    expectFailure(with(index), 1, "bad_index.obj:3: vertex index 7 out of range");
    const std::string garbage = writeFile("garbage.obj", std::string("this is not an obj\0\x01\xff", 21));
    expectFailure(with(garbage), 1, "garbage.obj: no vertices");
    const std::string empty = writeFile("empty.obj", "");
    expectFailure(with(empty), 1, "empty.obj");
}

TEST(SubdivCli, EveryShapeRunsOnTheNullBackend) {
    for (const char* name : {"catmark_cube.obj", "catmark_hole_test1.obj", "catmark_nonquads.obj",
                             "catmark_val2_interior.obj"}) {
        const std::vector<std::string> args = {"--backend", "null", "--crowd", "0", "--frames", "2",
                                               "--model", shape(name)};
        const ProcessResult run = runDemo(args);
        EXPECT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
    }
}
