// Overdraw (issue 32): the terrain flythrough at --tess-target 8 and the
// default showcase shade at most 2 fragments per pixel at 1280 x 720 on
// every backend, offscreen passes (the sun's and the characters' shadow
// maps) included. Pipeline statistics count fragment shader invocations
// exactly, so this is a count, not a timing: the figure of the median GPU
// frame of a short run (--benchmark's statsMedianFrame). One warm-up frame
// runs first and is not measured: the first frame also bakes the terrain's
// sun-visibility map once (terrain.sun, 1024 x 1024 fragments, 1.14 per
// pixel at this size), and on a loaded machine that frame's time can be the
// median of three (CI read 2.16 for the meshshader flythrough so).
#include "DemoProcess.h"
#include "TestFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace tessera::test;

namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr double kMostFragmentsPerPixel = 2.0;

class FragmentsPerPixel : public ::testing::TestWithParam<const char*> {};

/// Mesa's major version in a driver string ("llvmpipe Mesa 25.0.7-2~bpo12+1
/// (LLVM 15.0.6)"), or 0 where it names none (not Mesa).
int mesaMajor(const std::string& driver) {
    const size_t at = driver.find("Mesa ");
    return at == std::string::npos ? 0 : std::atoi(driver.c_str() + at + 5);
}

/// Fragment shader invocations per pixel of the median GPU frame of the
/// demo run with `args` on `backend`; negative (with a test failure) when
/// the run or its JSON fails. `driver` gets the report's driver string.
double fragmentsPerPixel(const std::string& backend, const std::string& name, std::vector<std::string> args,
                         std::string& driver) {
    const std::string json = (testOutputDir("fragments_per_pixel") / (name + "_" + backend + ".json")).string();
    args.insert(args.end(), {"--backend", backend, "--width", std::to_string(kWidth), "--height",
                             std::to_string(kHeight), "--warmup", "1", "--frames", "3", "--benchmark", json});
    const ProcessResult run = runDemo(args);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    if (run.exitCode != 0) return -1.0;
    std::ifstream in(json);
    const nlohmann::json report = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    driver = report["info"].value("driver", std::string());
    const nlohmann::json& stats = report["gpuFrame"]["statsMedianFrame"];
    EXPECT_TRUE(stats.is_object()) << json << ": no pipeline statistics";
    if (!stats.is_object()) return -1.0;
    const double fragments = stats["fragmentShaderInvocations"].get<double>();
    return fragments / (double(kWidth) * double(kHeight));
}

} // namespace

TEST_P(FragmentsPerPixel, TheFlythroughAndTheShowcaseShadeEachPixelAboutOnce) {
    const std::string backend = GetParam();
    if (!deviceRunsBackend(backend)) GTEST_SKIP() << "the device cannot run " << backend;
    std::string driver;
    const double flythrough =
        fragmentsPerPixel(backend, "flythrough", {"--scene", "terrain", "--tess-target", "8"}, driver);
    const double showcase = fragmentsPerPixel(backend, "showcase", {}, driver);
    std::cout << "[fragments per pixel] " << backend << ": flythrough " << flythrough << ", showcase " << showcase
              << " (1280 x 720, " << driver << ")\n";
    // The bound is stated for Mesa 25's lavapipe, the default device
    // `./tessera` installs, and for GPUs: Debian 12's own Mesa 22.3 read 5.9
    // for the flythrough on the day issue 32 was filed, a count this test
    // does not hold it to (docs/TERRAIN.md, "Overdraw").
    const int mesa = mesaMajor(driver);
    if (mesa > 0 && mesa < 25) GTEST_SKIP() << driver << ": the bound is checked from Mesa 25 on";
    EXPECT_GT(flythrough, 0.5);
    EXPECT_LE(flythrough, kMostFragmentsPerPixel);
    EXPECT_GT(showcase, 0.5);
    EXPECT_LE(showcase, kMostFragmentsPerPixel);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, FragmentsPerPixel, ::testing::Values("hulldomain", "streamout", "r2vb", "meshshader"),
                         [](const auto& test) { return test.param; });
