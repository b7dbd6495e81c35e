// The merged Perfetto trace: one process per backend, named, each shifted to
// start at 0, every event kept.

#include "ReportFixture.h"

#include "report/TraceMerge.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace fs = std::filesystem;
using namespace tessera;

namespace {

fs::path fixtureDir(const std::string& name) {
    fs::path dir = fs::path(TESSERA_TEST_OUTPUT_DIR) / "report" / name;
    fs::remove_all(dir);
    test::writeFixture(dir);
    return dir;
}

} // namespace

TEST(ReportMerge, OneProcessTrackPerBackend) {
    const fs::path dir = fixtureDir("merge");
    std::vector<report::TraceSource> sources;
    for (const char* b : test::kFixtureBackends)
        sources.push_back({b, dir / ("bench-" + std::string(b) + ".json")});
    auto merged = report::mergeTraces(sources);
    ASSERT_TRUE(merged) << merged.error().message;
    EXPECT_EQ(merged->backends, (std::vector<std::string>{"hulldomain", "r2vb", "streamout", "meshshader"}));
    const nlohmann::json root = nlohmann::json::parse(merged->json);
    const nlohmann::json& events = root.at("traceEvents");
    EXPECT_EQ(merged->events, events.size());
    std::map<int, std::string> processNames;
    std::map<int, double> firstTs;
    std::map<int, int> slices;
    for (const auto& e : events) {
        const int pid = e.at("pid").get<int>();
        if (e.at("ph") == "M" && e.at("name") == "process_name") {
            EXPECT_EQ(processNames.count(pid), 0u) << "one process_name per pid";
            processNames[pid] = e.at("args").at("name").get<std::string>();
        }
        if (e.contains("ts")) {
            const double ts = e.at("ts").get<double>();
            if (!firstTs.count(pid) || ts < firstTs[pid]) firstTs[pid] = ts;
        }
        if (e.at("ph") == "X") ++slices[pid];
    }
    ASSERT_EQ(processNames.size(), 4u);
    EXPECT_EQ(processNames[1], "hulldomain (llvmpipe (LLVM 15.0.6, 256 bits))");
    EXPECT_EQ(processNames[2].rfind("r2vb", 0), 0u);
    EXPECT_EQ(processNames[3].rfind("streamout", 0), 0u);
    EXPECT_EQ(processNames[4].rfind("meshshader", 0), 0u);
    for (int pid = 1; pid <= 4; ++pid) {
        EXPECT_DOUBLE_EQ(firstTs[pid], 0.0) << "pid " << pid << " starts at 0";
        EXPECT_EQ(slices[pid], 2) << "the frame and the GPU pass of pid " << pid;
    }
    // The sources' own thread names survive, under the new pid.
    bool threadName = false;
    for (const auto& e : events)
        if (e.at("name") == "thread_name" && e.at("pid") == 2) threadName = true;
    EXPECT_TRUE(threadName);
}

TEST(ReportMerge, MissingOrMalformedTracesAreNamed) {
    const fs::path dir = fixtureDir("merge-errors");
    auto missing = report::mergeTraces({{"r2vb", dir / "nope.json"}});
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().message,
              (dir / "nope.json").string() + ": no such file or cannot open it (r2vb's trace)");
    test::writeText(dir / "object.json", "{\"events\": []}");
    auto notTrace = report::mergeTraces({{"r2vb", dir / "object.json"}});
    ASSERT_FALSE(notTrace);
    EXPECT_EQ(notTrace.error().message,
              (dir / "object.json").string() + ": not a Chrome trace (no \"traceEvents\" array)");
}
