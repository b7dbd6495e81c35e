// Trace and benchmark files: content, JSON validity, and file errors.
#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/TraceWriter.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <unistd.h>

namespace tessera::profiler {
namespace {

using Json = nlohmann::ordered_json; // keeps the writers' member order, which some checks read

/// True when `actual` has every member of `expected` with an equal value,
/// recursively through objects; with `exact`, and no other members.
bool covers(const Json& actual, const Json& expected, bool exact) {
    if (!expected.is_object()) return actual == expected;
    if (!actual.is_object() || (exact && actual.size() != expected.size())) return false;
    for (const auto& [key, value] : expected.items()) {
        auto it = actual.find(key);
        if (it == actual.end() || !covers(*it, value, exact)) return false;
    }
    return true;
}

/// Index of the first of the trace's events that covers `expected` (see
/// covers), or -1 when none does.
long eventIndex(const Json& trace, const Json& expected, bool exact = false) {
    const Json& events = trace.at("traceEvents");
    for (size_t k = 0; k < events.size(); ++k)
        if (covers(events[k], expected, exact)) return long(k);
    return -1;
}

/// The event that is exactly `expected`, member for member.
bool hasExactEvent(const Json& trace, const char* expected) {
    return eventIndex(trace, Json::parse(expected), true) >= 0;
}

/// An event with at least the members of `expected`.
bool hasEventWith(const Json& trace, const char* expected) { return eventIndex(trace, Json::parse(expected)) >= 0; }

/// The benchmark report's series (a pass, or the GPU or CPU frame) named `name`.
const Json* seriesNamed(const Json& report, const std::string& name) {
    for (const Json& pass : report.at("passes"))
        if (pass.at("name") == name) return &pass;
    return nullptr;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::filesystem::path tempPath(const std::string& name) {
    return std::filesystem::path(::testing::TempDir()) /
           ("tessera_" + std::to_string(::getpid()) + "_" + name);
}

std::filesystem::path missingDirPath(const std::string& name) {
    return tempPath("no_such_dir") / name;
}

PipelineStatistics tessellatedStats(uint64_t triangles, uint64_t tessEvaluations) {
    PipelineStatistics s;
    s.inputAssemblyPrimitives = 16; // Patches.
    s.tessControlPatches = 16;
    s.tessEvaluationInvocations = tessEvaluations;
    s.clippingInvocations = triangles + 5;
    s.clippingPrimitives = triangles;
    return s;
}

/// A small recording with fixed times: frame 7 on "main" (thread 0), a scope
/// on worker thread 2, two GPU passes with statistics and one counter.
Profiler& fixedRecording(Profiler& profiler) {
    profiler.setEnabled(true);
    // Child recorded before its parent at the same start, as CpuScope does.
    profiler.recordCpu({"child", 0, 7, 1'000'000, 100'000, 1});
    profiler.recordCpu({"parent", 0, 7, 1'000'000, 400'000, 0});
    profiler.recordCpu({"decode", 2, 7, 1'200'000, 1'234, 0});
    profiler.recordGpuPass({"terrain", 7, 2'000'000, 1'500'000, tessellatedStats(100, 300)});
    profiler.recordGpuPass({"shadows \"cascade\"", 7, 3'600'000, 250'000, tessellatedStats(50, 200)});
    profiler.recordGpuPass({"blit", 7, 3'900'000, 10'000, std::nullopt});
    profiler.recordCounter({"memory MiB", 7, 2'500'000, 512.5});
    return profiler;
}

TEST(TraceWriter, WritesValidChromeTraceWithTracksPhasesAndMicroseconds) {
    Profiler profiler;
    fixedRecording(profiler);
    TraceMetadata metadata;
    metadata.backend = "pn-triangles";
    metadata.device = "Test GPU";
    metadata.width = 1920;
    std::string trace = makeChromeTrace(profiler, metadata);

    ASSERT_TRUE(Json::accept(trace)) << trace;
    const Json doc = Json::parse(trace);
    // The document opens with the display unit, then the events.
    ASSERT_GE(doc.size(), 2u);
    EXPECT_EQ(doc.begin().key(), "displayTimeUnit");
    EXPECT_EQ(doc.at("displayTimeUnit"), "ms");
    EXPECT_EQ(std::next(doc.begin()).key(), "traceEvents");
    EXPECT_TRUE(covers(doc.at("metadata"),
                       Json::parse(R"({"application":"tessera","backend":"pn-triangles","device":"Test GPU",)"
                                   R"("width":1920,"height":0})"),
                       false))
        << doc.at("metadata");
    // width and height close the metadata.
    EXPECT_EQ(std::prev(doc.at("metadata").end()).key(), "height");

    // Process and track names.
    EXPECT_TRUE(hasExactEvent(doc, R"({"name":"process_name","ph":"M","pid":1,"tid":0,"args":{"name":"tessera"}})"));
    EXPECT_TRUE(hasExactEvent(doc, R"({"name":"thread_name","ph":"M","pid":1,"tid":1,"args":{"name":"CPU main"}})"));
    EXPECT_TRUE(hasEventWith(doc, R"({"tid":3,"args":{"name":"CPU worker 2"}})"));
    EXPECT_TRUE(hasEventWith(doc, R"json({"tid":1000000,"args":{"name":"GPU (Test GPU)"}})json"));

    // Complete events in microseconds: 2,000,000 ns -> 2000, 1,500,000 ns -> 1500.
    EXPECT_TRUE(hasEventWith(doc, R"({"name":"terrain","cat":"gpu","ph":"X","pid":1,"tid":1000000,"ts":2000,"dur":1500,)"
                                  R"("args":{"frame":7,"inputAssemblyVertices":0,"inputAssemblyPrimitives":16,)"
                                  R"("tessEvaluationInvocations":300,"computeShaderInvocations":0,"triangles":100}})"));
    EXPECT_TRUE(hasEventWith(doc, R"({"name":"decode","cat":"cpu","ph":"X","pid":1,"tid":3,"ts":1200,"dur":1.234})"));
    EXPECT_TRUE(hasEventWith(doc, R"({"name":"shadows \"cascade\""})"));
    EXPECT_TRUE(hasExactEvent(
        doc, R"({"name":"blit","cat":"gpu","ph":"X","pid":1,"tid":1000000,"ts":3900,"dur":10,"args":{"frame":7}})"));
    // Parent precedes child despite being recorded after it.
    EXPECT_LT(eventIndex(doc, {{"name", "parent"}}), eventIndex(doc, {{"name", "child"}}));

    // Recorded and derived counters.
    EXPECT_TRUE(hasExactEvent(doc, R"({"name":"memory MiB","ph":"C","pid":1,"ts":2500,"args":{"value":512.5}})"));
    EXPECT_TRUE(hasExactEvent(doc, R"({"name":"triangles","ph":"C","pid":1,"ts":2000,"args":{"value":150}})"));
    EXPECT_TRUE(hasExactEvent(
        doc, R"({"name":"tess-evaluation invocations","ph":"C","pid":1,"ts":2000,"args":{"value":500}})"));
}

TEST(TraceWriter, RecordedFramesAppearOnTheirThreadTrack) {
    Profiler profiler;
    profiler.setEnabled(true);
    profiler.beginFrame(4);
    profiler.endFrame();
    std::string trace = makeChromeTrace(profiler, {});
    ASSERT_TRUE(Json::accept(trace)) << trace;
    const Json doc = Json::parse(trace);
    const uint32_t tid = Profiler::currentThreadId() + 1;
    EXPECT_GE(eventIndex(doc, {{"name", "frame"}, {"cat", "frame"}, {"ph", "X"}, {"pid", 1}, {"tid", tid},
                               {"args", {{"frame", 4}}}}),
              0)
        << trace;
    EXPECT_EQ(trace.find("GPU"), std::string::npos); // No passes, no GPU track.
}

TEST(TraceWriter, EmptyProfilerGivesValidTrace) {
    Profiler profiler;
    EXPECT_TRUE(Json::accept(makeChromeTrace(profiler, {})));
}

TEST(TraceWriter, WritesFileAndReportsBadPath) {
    Profiler profiler;
    fixedRecording(profiler);
    std::filesystem::path path = tempPath("trace.json");
    Status status = writeChromeTrace(profiler, path, {});
    ASSERT_TRUE(status.ok()) << status.error().message;
    EXPECT_EQ(readFile(path), makeChromeTrace(profiler, {}));
    std::filesystem::remove(path);

    std::filesystem::path bad = missingDirPath("trace.json");
    Status failed = writeChromeTrace(profiler, bad, {});
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().message.rfind(bad.string() + ": cannot open for writing: ", 0), 0u)
        << failed.error().message;
    EXPECT_GT(failed.error().message.size(), bad.string().size() + 27); // OS reason follows.
}

TEST(BenchmarkReport, WritesValidJsonWithPerFrameValues) {
    Profiler profiler;
    fixedRecording(profiler);
    profiler.recordGpuPass({"terrain", 8, 20'000'000, 2'500'000, tessellatedStats(100, 300)});
    BenchmarkInfo info{"pn-triangles", "Test GPU", "1.2.3", "canyon", 1280, 720, 10, 2};
    BenchmarkSummary summary = summarize(profiler);
    std::string report = makeBenchmarkJson(summary, info, profiler);

    ASSERT_TRUE(Json::accept(report)) << report;
    const Json doc = Json::parse(report);
    EXPECT_EQ(doc.at("info").at("scene"), "canyon");
    EXPECT_EQ(doc.at("info").at("warmupFrames"), 10);
    EXPECT_EQ(doc.at("frames"), 2);
    // The summary's frame count comes just before the GPU frame's series.
    auto frames = doc.find("frames");
    ASSERT_NE(frames, doc.end());
    EXPECT_EQ(std::next(frames).key(), "gpuFrame");
    const Json* terrain = seriesNamed(doc, "terrain");
    ASSERT_NE(terrain, nullptr) << report;
    EXPECT_TRUE(covers(*terrain,
                       Json::parse(R"({"samples":2,"minMs":1.5,"medianMs":2,"maxMs":2.5,"meanMs":2,)"
                                   R"("frameIndices":[7,8],"frameMs":[1.5,2.5]})"),
                       false))
        << *terrain;
    // blit has no statistics, nor has the CPU frame.
    EXPECT_TRUE(doc.at("cpuFrame").at("statsMedianFrame").is_null()) << report;
    ASSERT_NE(seriesNamed(doc, "blit"), nullptr);
    EXPECT_TRUE(seriesNamed(doc, "blit")->at("statsMedianFrame").is_null());

    std::filesystem::path path = tempPath("bench.json");
    Status status = writeBenchmarkJson(summary, info, profiler, path);
    ASSERT_TRUE(status.ok()) << status.error().message;
    EXPECT_EQ(readFile(path), report);
    std::filesystem::remove(path);

    std::filesystem::path bad = missingDirPath("bench.json");
    Status failed = writeBenchmarkJson(summary, info, profiler, bad);
    ASSERT_FALSE(failed.ok());
    EXPECT_NE(failed.error().message.find(bad.string()), std::string::npos);
}

} // namespace
} // namespace tessera::profiler
