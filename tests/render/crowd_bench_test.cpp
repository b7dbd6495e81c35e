// --bench crowd-sim: the crowd simulation's figures as JSON, on a machine
// without a Vulkan driver (the benchmark must not touch Vulkan). A short run
// on the 2 km crop of the content terrain; the figures are checked for
// presence and sense, never for speed.
#include "CrowdDemo.h"
#include "JsonFile.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

using namespace tessera::test;

namespace {

/// Hides every Vulkan driver from the loader while it lives.
class NoVulkanDriver {
public:
    NoVulkanDriver() {
        for (const char* name : kNames) setenv(name, "/nonexistent/tessera_icd.json", 1);
    }
    ~NoVulkanDriver() {
        for (const char* name : kNames) unsetenv(name);
    }

private:
    static constexpr const char* kNames[] = {"VK_ICD_FILENAMES", "VK_DRIVER_FILES"};
};

double number(const nlohmann::json& object, const std::string& key) {
    const auto v = numberAt(object, key);
    EXPECT_TRUE(v.has_value()) << "missing number \"" << key << "\"";
    return v.value_or(-1.0);
}

} // namespace

TEST(CrowdSimBench, WritesEveryFigureWithoutAVulkanDriver) {
    const std::filesystem::path out = testOutputDir("crowd") / "bench-crowd-sim.json";
    std::filesystem::remove(out);
    const std::vector<std::string> args = {"--bench",     "crowd-sim",         "--agents", "300,600",   "--steps",
                                           "20",          "--warmup",          "5",        "--threads", "1",
                                           "--heightmap", smallCrowdTerrain(), "--out",    out.string()};
    ProcessResult run;
    {
        NoVulkanDriver hidden;
        run = runDemo(args);
    }
    ASSERT_EQ(run.exitCode, 0) << demoCommandLine(args) << "\n" << run.output;
    nlohmann::json doc;
    std::string error;
    ASSERT_TRUE(readJsonFile(out, doc, error)) << error;
    EXPECT_EQ(stringAt(doc, "format").value_or(""), "tessera-bench-crowd-sim");
    EXPECT_EQ(number(doc, "warmup_steps"), 5.0);
    EXPECT_EQ(number(doc, "steps"), 20.0);
    EXPECT_EQ(number(doc, "threads"), 1.0);
    EXPECT_GE(number(doc, "cpu_cores"), 1.0);
    EXPECT_FALSE(stringAt(doc, "cpu_model").value_or("").empty());
    const nlohmann::json* runs = memberOf(doc, "runs");
    ASSERT_TRUE(runs && runs->is_array()) << "no \"runs\" array";
    ASSERT_EQ(runs->size(), 2u);
    double agents = 300.0;
    for (const nlohmann::json& r : *runs) {
        SCOPED_TRACE(agents);
        EXPECT_EQ(number(r, "agents"), agents);
        agents *= 2.0;
        EXPECT_GT(number(r, "create_ms"), 0.0);
        for (const char* series : {"step_ms", "fields_ms", "avoidance_ms", "integration_ms", "wall_ms"}) {
            const nlohmann::json* s = memberOf(r, series);
            ASSERT_TRUE(s && s->is_object()) << "missing \"" << series << "\"";
            EXPECT_GE(number(*s, "median"), 0.0) << series;
            EXPECT_GE(number(*s, "max"), number(*s, "median")) << series;
            EXPECT_GE(number(*s, "max"), number(*s, "mean")) << series;
        }
        EXPECT_GT(number(*memberOf(r, "step_ms"), "max"), 0.0);
        EXPECT_GT(number(r, "bytes_per_agent"), 0.0);
        EXPECT_GT(number(r, "field_bytes"), 0.0);
        for (const char* overlap : {"overlap_end", "overlap_worst_sampled"}) {
            const nlohmann::json* o = memberOf(r, overlap);
            ASSERT_TRUE(o && o->is_object()) << "missing \"" << overlap << "\"";
            for (const char* key : {"pairs", "worst", "overlapping"}) EXPECT_GE(number(*o, key), 0.0) << overlap;
        }
        for (const char* key : {"arrivals", "stuck_end", "fleeing_max", "field_tiles_solved_mean", "impacts"})
            EXPECT_GE(number(r, key), 0.0) << key;
        EXPECT_NEAR(number(r, "simulated_seconds"), 25.0 / 30.0, 1e-3);
    }
    std::cout << run.output;
}
