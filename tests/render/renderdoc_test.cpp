// --renderdoc N: a frame capture through RenderDoc's in-application API when
// librenderdoc.so is there, and a clear warning (exit 0, the run goes on)
// when it is not.
#include "DemoProcess.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace tessera::test;

namespace {

const std::vector<std::string> kSmallRun = {"--backend", "r2vb", "--scene", "terrain", "--width", "96",
                                            "--height", "64", "--frames", "3", "--validation"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

/// RenderDoc's library as the demo would load it (Debian's librenderdoc).
bool renderDocInstalled() { return std::filesystem::exists("/usr/lib/librenderdoc.so"); }

} // namespace

TEST(RenderDoc, WithoutRenderDocTheRunWarnsAndGoesOn) {
    setenv("TESSERA_RENDERDOC_LIBRARY", "/nonexistent/librenderdoc.so", 1);
    auto run = runDemo(with(kSmallRun, {"--renderdoc", "1"}));
    unsetenv("TESSERA_RENDERDOC_LIBRARY");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("--renderdoc: RenderDoc is not available: /nonexistent/librenderdoc.so"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("install Debian's renderdoc package"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;
}

TEST(RenderDoc, AFileThatIsNotRenderDocIsNamed) {
    const std::string bogus = std::string(TESSERA_TEST_OUTPUT_DIR) + "/not_renderdoc.so";
    std::ofstream(bogus) << "not a library";
    setenv("TESSERA_RENDERDOC_LIBRARY", bogus.c_str(), 1);
    auto run = runDemo(with(kSmallRun, {"--renderdoc", "0"}));
    unsetenv("TESSERA_RENDERDOC_LIBRARY");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find(bogus), std::string::npos) << run.output;
}

TEST(RenderDoc, AFrameBeyondTheRunIsSaid) {
    auto run = runDemo(with(kSmallRun, {"--renderdoc", "50"}));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("the run ended after 3 frames, so nothing was captured"), std::string::npos)
        << run.output;
}

// With RenderDoc there: frame 1 captured into a RenderDoc file, or, where
// RenderDoc's layer leaves no device Tessera can use (Debian 12's RenderDoc
// 1.24 reports lavapipe as Vulkan 1.2; on an H100 it captures every
// backend), a warning that says so and the run without a capture.
TEST(RenderDoc, CapturesTheFrameAskedOrSaysWhyNot) {
    if (!renderDocInstalled()) GTEST_SKIP() << "librenderdoc.so is not installed (Debian's librenderdoc)";
    const std::filesystem::path prefix = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "renderdoc" / "terrain";
    std::filesystem::remove_all(prefix.parent_path());
    std::filesystem::create_directories(prefix.parent_path());
    auto run = runDemo(with(kSmallRun, {"--renderdoc", "1", "--renderdoc-file", prefix.string()}));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;
    const std::string marker = "RenderDoc capture of frame 1: ";
    const size_t at = run.output.find(marker);
    if (at == std::string::npos) {
        EXPECT_NE(run.output.find("--renderdoc: RenderDoc's layer (API "), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("rendering without a capture"), std::string::npos) << run.output;
        GTEST_SKIP() << "RenderDoc's layer hides the Vulkan 1.3 device here; the run said so and went on";
    }
    const std::string file = run.output.substr(at + marker.size(), run.output.find('\n', at) - at - marker.size());
    EXPECT_EQ(std::filesystem::path(file).parent_path(), prefix.parent_path()) << file;
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    EXPECT_EQ(std::string(magic, 4), "RDOC") << file << " is not a RenderDoc capture";
}
