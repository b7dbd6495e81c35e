// The report's inputs: every way a bench JSON can be missing or malformed
// gives one line naming the file and the problem, in the library and from
// the tool (exit 1; a bad command line exits 2).

#include "ReportFixture.h"
#include "ToolProcess.h"

#include "report/BenchInput.h"
#include "report/ReportWriter.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace tessera;

namespace {

fs::path outDir(const std::string& name) {
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "report" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string parseError(const std::string& text) {
    auto parsed = report::parseBenchRecords(text, "in.json");
    return parsed ? std::string("(parsed)") : parsed.error().message;
}

} // namespace

TEST(ReportInput, ReadsTheBenchmarkRecords) {
    auto records = report::parseBenchRecords(test::fixtureRecords().dump(), "bench.json");
    ASSERT_TRUE(records) << records.error().message;
    ASSERT_EQ(records->size(), 16u);
    const report::BenchRecord& r2vb = records->at(1);
    EXPECT_EQ(r2vb.backend, "r2vb");
    EXPECT_EQ(r2vb.rowLabel(), "far lowres");
    ASSERT_EQ(r2vb.passes.size(), 4u);
    EXPECT_EQ(r2vb.passes.back().name, "terrain.lowres");
    EXPECT_DOUBLE_EQ(r2vb.passes.back().gpuMs, 0.13);
    EXPECT_DOUBLE_EQ(r2vb.cpuFrameMs, 30.0);
    EXPECT_EQ(report::backendsOf(*records),
              (std::vector<std::string>{"hulldomain", "r2vb", "streamout", "meshshader"}));
}

TEST(ReportInput, MalformedJsonNamesTheFileAndWhere) {
    const std::string message = parseError("[{\"backend\": \"r2vb\",");
    EXPECT_EQ(message.rfind("in.json: malformed JSON (parse error", 0), 0u) << message;
    EXPECT_NE(message.find("line 1"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(ReportInput, WrongShapesAreNamed) {
    EXPECT_EQ(parseError("{\"a\": 1}"),
              "in.json: expected a JSON array of benchmark records (tessera-demo --bench terrain --out), got object");
    EXPECT_EQ(parseError("[]"), "in.json: holds no benchmark records");
    EXPECT_EQ(parseError("[3]"), "in.json: record 1 is not an object");
    nlohmann::json records = test::fixtureRecords();
    records[2].erase("cpu_frame_ms_median");
    EXPECT_EQ(parseError(records.dump()), "in.json: record 3 has no \"cpu_frame_ms_median\"");
    records = test::fixtureRecords();
    records[0]["gpu_ms_median"] = "fast";
    EXPECT_EQ(parseError(records.dump()), "in.json: record 1: \"gpu_ms_median\" is not a number");
    records = test::fixtureRecords();
    records[1].erase("pass:r2vb.cage:gpu_ms_median");
    EXPECT_EQ(parseError(records.dump()), "in.json: record 2 has no \"pass:r2vb.cage:gpu_ms_median\"");
    records = test::fixtureRecords();
    records[0]["clipping_invocations"] = -4;
    EXPECT_EQ(parseError(records.dump()), "in.json: record 1: \"clipping_invocations\" is not a whole number");
}

TEST(ReportInput, MissingFileIsNamed) {
    const fs::path dir = outDir("missing");
    auto loaded = report::loadBenchRecords(dir / "bench.json");
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().message.rfind((dir / "bench.json").string() + ": no such file", 0), 0u)
        << loaded.error().message;
    auto folder = report::loadBenchRecords(dir);
    ASSERT_FALSE(folder);
    EXPECT_EQ(folder.error().message, dir.string() + ": is a folder, not a JSON file");
}

TEST(ReportInput, WriterFailsOnAMalformedTrace) {
    const fs::path dir = outDir("bad-trace");
    test::writeFixture(dir);
    test::writeText(dir / "bench-r2vb.json", "{\"traceEvents\": [");
    auto written = report::writeReport({dir, dir / "report.html", {}, {}, {}});
    ASSERT_FALSE(written);
    EXPECT_EQ(written.error().message, (dir / "bench-r2vb.json").string() + ": malformed JSON (r2vb's trace)");
}

TEST(ReportInput, WriterNotesMissingOptionalInputs) {
    const fs::path dir = outDir("no-extras");
    test::writeText(dir / "bench.json", test::fixtureRecords().dump());
    auto written = report::writeReport({dir, dir / "report.html", {}, {}, {}});
    ASSERT_TRUE(written) << written.error().message;
    EXPECT_EQ(written->notes.size(), 8u); // four traces, four screenshots
    EXPECT_TRUE(written->trace.empty());
    EXPECT_TRUE(fs::exists(dir / "report.html"));
}

TEST(ReportTool, MissingInputExitsOneWithOneLine) {
    const fs::path dir = outDir("tool-missing");
    auto run = test::runProgram(TESSERA_REPORT_EXE, {"--dir", dir.string()});
    EXPECT_EQ(run.exitCode, 1) << run.output;
    const auto lines = test::linesOf(run.output);
    ASSERT_EQ(lines.size(), 1u) << run.output;
    EXPECT_EQ(lines[0].rfind("tessera-report: " + (dir / "bench.json").string() + ": no such file", 0), 0u) << lines[0];
}

TEST(ReportTool, MalformedInputExitsOneWithOneLine) {
    const fs::path dir = outDir("tool-malformed");
    test::writeText(dir / "bench.json", "[{\"backend\": ");
    auto run = test::runProgram(TESSERA_REPORT_EXE, {"--dir", dir.string()});
    EXPECT_EQ(run.exitCode, 1) << run.output;
    const auto lines = test::linesOf(run.output);
    ASSERT_EQ(lines.size(), 1u) << run.output;
    EXPECT_NE(lines[0].find((dir / "bench.json").string() + ": malformed JSON"), std::string::npos) << lines[0];
}

TEST(ReportTool, BadFlagsExitTwo) {
    auto unknown = test::runProgram(TESSERA_REPORT_EXE, {"--frobnicate"});
    EXPECT_EQ(unknown.exitCode, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("unknown option \"--frobnicate\""), std::string::npos) << unknown.output;
    auto noDir = test::runProgram(TESSERA_REPORT_EXE, {});
    EXPECT_EQ(noDir.exitCode, 2) << noDir.output;
    EXPECT_NE(noDir.output.find("--dir DIR is required"), std::string::npos) << noDir.output;
    auto runOnly = test::runProgram(TESSERA_REPORT_EXE, {"--dir", "x", "--width", "320"});
    EXPECT_EQ(runOnly.exitCode, 2) << runOnly.output;
    EXPECT_NE(runOnly.output.find("need --run"), std::string::npos) << runOnly.output;
    auto help = test::runProgram(TESSERA_REPORT_EXE, {"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.output.find("--run"), std::string::npos);
}

TEST(ReportTool, WritesTheReportAndTheMergedTrace) {
    const fs::path dir = outDir("tool-ok");
    test::writeFixture(dir);
    auto run = test::runProgram(TESSERA_REPORT_EXE, {"--dir", dir.string()});
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir / "report.html"));
    EXPECT_TRUE(fs::exists(dir / "report-trace.json"));
    EXPECT_NE(run.output.find("4 timings flagged"), std::string::npos) << run.output;
}

TEST(ReportInput, FindsTracesTheRecordsName) {
    // A benchmark run with --out-dir elsewhere: the records name the traces.
    const fs::path dir = outDir("named-traces");
    const fs::path traces = outDir("named-traces-elsewhere");
    test::writeFixture(dir);
    nlohmann::json records = test::fixtureRecords();
    for (auto& r : records) {
        const std::string name = "bench-" + r["backend"].get<std::string>() + ".json";
        if (fs::exists(dir / name)) fs::rename(dir / name, traces / name);
        r["trace"] = (traces / name).string();
    }
    test::writeText(dir / "bench.json", records.dump());
    auto written = report::writeReport({dir, dir / "report.html", {}, {}, {}});
    ASSERT_TRUE(written) << written.error().message;
    EXPECT_TRUE(written->notes.empty()) << written->notes.front();
    EXPECT_FALSE(written->trace.empty());
}

TEST(ReportTool, ARunThatCannotStartOrFailsExitsOne) {
    const fs::path dir = outDir("tool-run-fails");
    auto missing = test::runProgram(TESSERA_REPORT_EXE, {"--run", "--dir", dir.string(), "--demo", "/nonexistent/demo"});
    EXPECT_EQ(missing.exitCode, 1) << missing.output;
    EXPECT_NE(missing.output.find("tessera-report: /nonexistent/demo: no tessera-demo to run"), std::string::npos)
        << missing.output;
    // A demo that fails: the report names the command line and its status.
    auto failed = test::runProgram(TESSERA_REPORT_EXE, {"--run", "--dir", dir.string(), "--demo", "/bin/false"});
    EXPECT_EQ(failed.exitCode, 1) << failed.output;
    EXPECT_NE(failed.output.find("/bin/false --bench terrain --backend all"), std::string::npos) << failed.output;
    EXPECT_NE(failed.output.find(": exited with status 1"), std::string::npos) << failed.output;
    EXPECT_FALSE(fs::exists(dir / "report.html"));
}
