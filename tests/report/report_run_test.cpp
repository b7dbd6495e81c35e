// tessera-report --run end to end: it runs the tessera-demo beside it for
// the terrain benchmark on every backend and a screenshot per backend, then
// writes the report (label render: it renders, on lavapipe in about 20 s).

#include "ToolProcess.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using namespace tessera;

TEST(ReportRun, MeasuresEveryBackendAndWritesTheReport) {
    const fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "report" / "run";
    fs::remove_all(dir);
    // The smallest run that still draws every row: 64x36, one frame a row.
    auto run = test::runProgram(TESSERA_REPORT_EXE, {"--run", "--dir", dir.string(), "--width", "64", "--height", "36",
                                                  "--frames", "1", "--warmup", "0"});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream benchFile(dir / "bench.json");
    const nlohmann::json records = nlohmann::json::parse(benchFile);
    std::set<std::string> backends;
    for (const auto& r : records) backends.insert(r.at("backend").get<std::string>());
    ASSERT_FALSE(backends.empty());
    std::ostringstream html;
    html << std::ifstream(dir / "report.html").rdbuf();
    for (const std::string& b : backends) {
        EXPECT_TRUE(fs::exists(dir / ("screenshot-" + b + ".png"))) << b;
        EXPECT_NE(html.str().find("href=\"bench-" + b + ".json\""), std::string::npos) << b;
        EXPECT_NE(html.str().find("<figure class=\"shot\" data-backend=\"" + b + "\">"), std::string::npos) << b;
    }
    std::ifstream traceFile(dir / "report-trace.json");
    const nlohmann::json trace = nlohmann::json::parse(traceFile);
    std::set<int> processes;
    for (const auto& e : trace.at("traceEvents"))
        if (e.at("ph") == "M" && e.at("name") == "process_name") processes.insert(e.at("pid").get<int>());
    EXPECT_EQ(processes.size(), backends.size());
}
