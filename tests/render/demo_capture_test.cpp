// Profiling outputs: the Chrome trace has CPU and GPU tracks with GPU pass
// events of non-zero duration, and the benchmark JSON has per-pass figures.
#include "DemoProcess.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

using namespace tessera::test;

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace

TEST(DemoCapture, TraceHasGpuPassesWithDurationAndCounters) {
    const std::string out = TESSERA_TEST_OUTPUT_DIR;
    const std::string trace = out + "/capture.json", bench = out + "/benchmark.json";
    auto run = runDemo({"--scene", "terrain", "--backend", "hulldomain", "--frames", "6", "--warmup", "2", "--width", "160", "--height", "90",
                        "--capture", trace, "--benchmark", bench, "--validation"});
    ASSERT_EQ(run.exitCode, 0) << run.output;

    const std::string json = slurp(trace);
    ASSERT_FALSE(json.empty());
    EXPECT_NE(json.find("\"traceEvents\""), std::string::npos);
    EXPECT_NE(json.find("CPU main"), std::string::npos);
    EXPECT_NE(json.find("GPU ("), std::string::npos);
    EXPECT_NE(json.find("\"name\":\"triangles\""), std::string::npos) << "triangle counter missing";
    int gpuPasses = 0, positive = 0;
    for (size_t at = json.find("\"cat\":\"gpu\""); at != std::string::npos; at = json.find("\"cat\":\"gpu\"", at + 1)) {
        const size_t dur = json.find("\"dur\":", at);
        ASSERT_NE(dur, std::string::npos);
        ++gpuPasses;
        positive += std::strtod(json.c_str() + dur + 6, nullptr) > 0.0;
    }
    EXPECT_GE(gpuPasses, 6);
    EXPECT_EQ(positive, gpuPasses) << "every GPU pass must have a measured duration";

    const std::string report = slurp(bench);
    for (const char* key : {"terrain.factors", "terrain.adaptive", "median", "llvmpipe", "hulldomain"})
        EXPECT_NE(report.find(key), std::string::npos) << key << " missing from the benchmark JSON";
}
