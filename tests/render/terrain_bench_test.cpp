// --bench terrain: the first paper's Table 2 as JSON, one record per device,
// backend, view (far, close) and mode (adaptive once per metric unless
// --tess-metric picks one), with triangle counts and GPU times.
#include "DemoProcess.h"
#include "TestFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

using namespace tessera::test;

namespace {

/// One flat JSON object: key -> raw value text (strings without their quotes).
using Record = std::map<std::string, std::string>;

std::string joined(const std::vector<std::string>& args) {
    std::string text = "tessera-demo";
    for (const auto& a : args) {
        text += ' ';
        text += shellQuote(a);
    }
    return text;
}

/// Parses a JSON list of flat objects whose values are strings or numbers;
/// returns false (with `error`) on anything else.
bool parseRecords(const std::string& s, std::vector<Record>& records, std::string& error) {
    const nlohmann::json list = nlohmann::json::parse(s, nullptr, /*allow_exceptions=*/false);
    if (list.is_discarded()) return error = "not JSON", false;
    if (!list.is_array()) return error = "not a list", false;
    for (const nlohmann::json& object : list) {
        if (!object.is_object()) return error = "a list item is not an object", false;
        Record record;
        for (const auto& [key, value] : object.items()) {
            if (value.is_string()) record[key] = value.get<std::string>();
            else if (value.is_number()) record[key] = value.dump();
            else return error = "\"" + key + "\" is not a string or a number", false;
        }
        records.push_back(std::move(record));
    }
    return true;
}

double number(const Record& r, const std::string& key) {
    return std::strtod(r.at(key).c_str(), nullptr);
}

/// Every record has the documented keys with sensible values.
void expectWellFormed(const std::vector<Record>& records, int width, int height) {
    for (const auto& r : records) {
        for (const char* key : {"backend", "mode", "view", "width", "height", "triangles", "gpu_ms_median",
                                "gpu_ms_min", "gpu_ms_max", "device"})
            ASSERT_TRUE(r.count(key)) << "record without \"" << key << "\"";
        EXPECT_EQ(r.at("backend"), "hulldomain");
        EXPECT_NE(r.at("device").find("llvmpipe"), std::string::npos) << r.at("device");
        EXPECT_TRUE(r.at("view") == "far" || r.at("view") == "close") << r.at("view");
        EXPECT_EQ(number(r, "width"), width);
        EXPECT_EQ(number(r, "height"), height);
        EXPECT_GT(number(r, "triangles"), 0.0) << r.at("view") << " " << r.at("mode");
        EXPECT_GT(number(r, "gpu_ms_median"), 0.0);
        EXPECT_LE(number(r, "gpu_ms_min"), number(r, "gpu_ms_median"));
        EXPECT_LE(number(r, "gpu_ms_median"), number(r, "gpu_ms_max"));
        // The frame's fragments (issue 32's overdraw figure), over the pixels.
        ASSERT_TRUE(r.count("fragment_shader_invocations") && r.count("fragments_per_pixel"));
        EXPECT_GT(number(r, "fragments_per_pixel"), 0.0);
        EXPECT_NEAR(number(r, "fragments_per_pixel"),
                    number(r, "fragment_shader_invocations") / (number(r, "width") * number(r, "height")), 1e-3);
    }
}

/// Triangles of the first record of `view` and `mode` (and `metric` when
/// given), or -1 when there is none.
double triangles(const std::vector<Record>& records, const std::string& view, const std::string& mode,
                 const std::string& metric = "") {
    for (const auto& r : records) {
        if (r.at("view") != view || r.at("mode") != mode) continue;
        if (!metric.empty() && (!r.count("metric") || r.at("metric") != metric)) continue;
        return number(r, "triangles");
    }
    return -1.0;
}

/// Runs the demo with stdout alone captured (stderr goes to a file), so the
/// JSON on stdout can be checked without the log lines.
ProcessResult runDemoStdout(const std::vector<std::string>& args, const std::string& stderrPath) {
    std::string command = "ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" " + shellQuote(TESSERA_DEMO_EXE);
    for (const auto& a : args) {
        command += ' ';
        command += shellQuote(a);
    }
    command += " 2>";
    command += shellQuote(stderrPath);
    ProcessResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    size_t n;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

std::vector<std::string> benchArgs(int width, int height) {
    return {"--bench",
            "terrain",
            "--backend",
            "hulldomain",
            "--device",
            "llvmpipe",
            "--validation",
            "--width",
            std::to_string(width),
            "--height",
            std::to_string(height),
            "--frames",
            "2",
            "--warmup",
            "1"};
}

} // namespace

// One metric: 3 modes x 2 views, and adaptive draws more than the control mesh
// and less than continuous tessellation in both views.
TEST(TerrainBench, OneMetricGivesSixRecordsOrderedByTriangles) {
    const std::string out = (testOutputDir("terrain_bench") / "bench_screen.json").string();
    std::filesystem::remove(out);
    auto args = benchArgs(320, 180);
    args.insert(args.end(), {"--tess-metric", "screen", "--out", out});
    const auto run = runDemo(args);
    ASSERT_EQ(run.exitCode, 0) << joined(args) << "\n" << run.output;
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;

    std::vector<Record> records;
    std::string error;
    ASSERT_TRUE(parseRecords(readTextFile(out), records, error)) << out << ": " << error;
    ASSERT_EQ(records.size(), 6u) << out;
    expectWellFormed(records, 320, 180);
    for (const char* view : {"far", "close"}) {
        SCOPED_TRACE(view);
        const double low = triangles(records, view, "lowres"), adaptive = triangles(records, view, "adaptive"),
                     continuous = triangles(records, view, "continuous");
        ASSERT_GT(low, 0.0) << "no lowres record";
        ASSERT_GT(adaptive, 0.0) << "no adaptive record";
        ASSERT_GT(continuous, 0.0) << "no continuous record";
        EXPECT_LT(low, adaptive);
        EXPECT_LT(adaptive, continuous);
    }
}

// The brief's command line, without --tess-metric: adaptive once per metric,
// so 2 views x (lowres, continuous, 4 metrics) = 12 records. At 160x90 the
// far view's patches are already under 16 px, so the screen-space metrics may
// stay at level 1 (as many triangles as lowres) but never fewer.
TEST(TerrainBench, EveryMetricWritesAnAdaptiveRecordPerView) {
    const std::string out = (testOutputDir("terrain_bench") / "bench_all.json").string();
    std::filesystem::remove(out);
    auto args = benchArgs(160, 90);
    args.insert(args.end(), {"--out", out});
    const auto run = runDemo(args);
    ASSERT_EQ(run.exitCode, 0) << joined(args) << "\n" << run.output;
    EXPECT_NE(run.output.find("validation messages: 0"), std::string::npos) << run.output;

    std::vector<Record> records;
    std::string error;
    ASSERT_TRUE(parseRecords(readTextFile(out), records, error)) << out << ": " << error;
    ASSERT_EQ(records.size(), 12u) << out;
    expectWellFormed(records, 160, 90);
    for (const char* view : {"far", "close"}) {
        SCOPED_TRACE(view);
        const double low = triangles(records, view, "lowres");
        ASSERT_GT(low, 0.0) << "no lowres record";
        EXPECT_GT(triangles(records, view, "continuous"), low);
        for (const char* metric : {"screen", "distance", "silhouette", "detail"}) {
            const double adaptive = triangles(records, view, "adaptive", metric);
            ASSERT_GT(adaptive, 0.0) << "no adaptive " << metric << " record";
            EXPECT_GE(adaptive, low) << metric;
            if (std::string(view) == "close") {
                EXPECT_GT(adaptive, low) << metric;
            }
        }
    }
}

TEST(TerrainBench, WithoutOutTheJsonGoesToStdout) {
    const std::string errPath = (testOutputDir("terrain_bench") / "bench_stdout.stderr.txt").string();
    auto args = benchArgs(160, 90);
    args.insert(args.end(), {"--tess-metric", "detail"});
    const auto run = runDemoStdout(args, errPath);
    const std::string err = readTextFile(errPath);
    ASSERT_EQ(run.exitCode, 0) << joined(args) << "\nstdout:\n" << run.output << "\nstderr:\n" << err;

    const size_t first = run.output.find_first_not_of(" \t\r\n");
    ASSERT_NE(first, std::string::npos) << "nothing on stdout; stderr:\n" << err;
    EXPECT_EQ(run.output[first], '[') << "stdout should be the JSON list:\n" << run.output;
    std::vector<Record> records;
    std::string error;
    ASSERT_TRUE(parseRecords(run.output, records, error)) << error << "\nstdout:\n" << run.output;
    EXPECT_EQ(records.size(), 6u);
    expectWellFormed(records, 160, 90);
}
