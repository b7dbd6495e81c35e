// Profiling outputs: the Chrome trace has CPU and GPU tracks with GPU pass
// events of non-zero duration, and the benchmark JSON has per-pass figures.
#include "DemoProcess.h"
#include "JsonFile.h"

#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <string>

using namespace tessera::test;

TEST(DemoCapture, TraceHasGpuPassesWithDurationAndCounters) {
    const std::string out = TESSERA_TEST_OUTPUT_DIR;
    const std::string trace = out + "/capture.json", bench = out + "/benchmark.json";
    auto run = runDemo({"--scene", "terrain", "--backend", "hulldomain", "--frames", "6", "--warmup", "2", "--width", "160", "--height", "90",
                        "--capture", trace, "--benchmark", bench, "--validation"});
    ASSERT_EQ(run.exitCode, 0) << run.output;

    nlohmann::json doc;
    std::string error;
    ASSERT_TRUE(readJsonFile(trace, doc, error)) << trace << ": " << error;
    const nlohmann::json* events = memberOf(doc, "traceEvents");
    ASSERT_TRUE(events && events->is_array()) << trace;
    bool cpuMain = false, gpuTrack = false, triangles = false;
    int gpuPasses = 0, positive = 0;
    for (const nlohmann::json& e : *events) {
        const nlohmann::json* args = memberOf(e, "args");
        const std::string track = args ? stringAt(*args, "name").value_or("") : "";
        cpuMain |= track == "CPU main";
        gpuTrack |= track.rfind("GPU (", 0) == 0;
        triangles |= stringAt(e, "name") == "triangles";
        if (stringAt(e, "cat") != "gpu") continue;
        const std::optional<double> dur = numberAt(e, "dur");
        ASSERT_TRUE(dur.has_value()) << e;
        ++gpuPasses;
        positive += *dur > 0.0;
    }
    EXPECT_TRUE(cpuMain) << "no CPU main track";
    EXPECT_TRUE(gpuTrack) << "no GPU track";
    EXPECT_TRUE(triangles) << "triangle counter missing";
    EXPECT_GE(gpuPasses, 6);
    EXPECT_EQ(positive, gpuPasses) << "every GPU pass must have a measured duration";

    nlohmann::json report;
    ASSERT_TRUE(readJsonFile(bench, report, error)) << bench << ": " << error;
    std::set<std::string> passes;
    if (const nlohmann::json* list = memberOf(report, "passes"); list && list->is_array())
        for (const nlohmann::json& pass : *list) passes.insert(stringAt(pass, "name").value_or(""));
    for (const char* pass : {"terrain.factors", "terrain.adaptive"})
        EXPECT_EQ(passes.count(pass), 1u) << pass << " missing from the benchmark JSON";
    const nlohmann::json* gpuFrame = memberOf(report, "gpuFrame");
    EXPECT_TRUE(gpuFrame && numberAt(*gpuFrame, "medianMs")) << "no median in the benchmark JSON";
    const nlohmann::json* info = memberOf(report, "info");
    ASSERT_NE(info, nullptr) << bench;
    EXPECT_NE(stringAt(*info, "device").value_or("").find("llvmpipe"), std::string::npos) << *info;
    EXPECT_EQ(stringAt(*info, "backend"), "hulldomain");
}
