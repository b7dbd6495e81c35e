// Trace and benchmark files: content, JSON validity, and file errors.
#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/TraceWriter.h"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace tessera::profiler {
namespace {

/// Strict RFC 8259 recogniser: true when `text` is exactly one JSON value.
class JsonValidator {
public:
    static bool isValid(std::string_view text) {
        JsonValidator v(text);
        v.skipSpace();
        if (!v.parseValue(0)) return false;
        v.skipSpace();
        return v.mPos == text.size();
    }

private:
    explicit JsonValidator(std::string_view text) : mText(text) {}

    bool parseValue(int depth) {
        if (depth > 256 || mPos >= mText.size()) return false;
        switch (mText[mPos]) {
        case '{': return parseContainer(depth, '}', true);
        case '[': return parseContainer(depth, ']', false);
        case '"': return parseString();
        case 't': return literal("true");
        case 'f': return literal("false");
        case 'n': return literal("null");
        default: return parseNumber();
        }
    }

    bool parseContainer(int depth, char close, bool isObject) {
        ++mPos;
        skipSpace();
        if (peek() == close) {
            ++mPos;
            return true;
        }
        for (;;) {
            skipSpace();
            if (isObject) {
                if (peek() != '"' || !parseString()) return false;
                skipSpace();
                if (peek() != ':') return false;
                ++mPos;
                skipSpace();
            }
            if (!parseValue(depth + 1)) return false;
            skipSpace();
            if (peek() == close) {
                ++mPos;
                return true;
            }
            if (peek() != ',') return false;
            ++mPos;
        }
    }

    bool parseString() {
        ++mPos;
        while (mPos < mText.size()) {
            auto c = static_cast<unsigned char>(mText[mPos++]);
            if (c == '"') return true;
            if (c < 0x20) return false;
            if (c != '\\') continue;
            char e = peek();
            ++mPos;
            if (e == 'u') {
                for (int i = 0; i < 4; ++i, ++mPos) {
                    if (!std::isxdigit(static_cast<unsigned char>(peek()))) return false;
                }
            } else if (std::string_view("\"\\/bfnrt").find(e) == std::string_view::npos) {
                return false;
            }
        }
        return false;
    }

    bool parseNumber() {
        if (peek() == '-') ++mPos;
        if (peek() == '0') {
            ++mPos;
        } else if (!digits()) {
            return false;
        }
        if (peek() == '.') {
            ++mPos;
            if (!digits()) return false;
        }
        if (peek() == 'e' || peek() == 'E') {
            ++mPos;
            if (peek() == '+' || peek() == '-') ++mPos;
            if (!digits()) return false;
        }
        return true;
    }

    bool digits() {
        size_t start = mPos;
        while (std::isdigit(static_cast<unsigned char>(peek()))) ++mPos;
        return mPos > start;
    }

    bool literal(std::string_view word) {
        if (mText.substr(mPos, word.size()) != word) return false;
        mPos += word.size();
        return true;
    }

    char peek() const { return mPos < mText.size() ? mText[mPos] : '\0'; }
    void skipSpace() {
        while (mPos < mText.size() && std::string_view(" \t\n\r").find(mText[mPos]) != std::string_view::npos) ++mPos;
    }

    std::string_view mText;
    size_t mPos = 0;
};

TEST(JsonValidator, AcceptsValidAndRejectsInvalidDocuments) {
    EXPECT_TRUE(JsonValidator::isValid(R"({"a":[1,-0.5,2e+3,true,null,"x\n\u00e9"],"b":{}})"));
    EXPECT_TRUE(JsonValidator::isValid(" [ ] "));
    EXPECT_FALSE(JsonValidator::isValid(R"({"a":1,})"));
    EXPECT_FALSE(JsonValidator::isValid(R"([1 2])"));
    EXPECT_FALSE(JsonValidator::isValid(R"({"a" 1})"));
    EXPECT_FALSE(JsonValidator::isValid(R"(["\x"])"));
    EXPECT_FALSE(JsonValidator::isValid("[\"a\nb\"]"));
    EXPECT_FALSE(JsonValidator::isValid("[01]"));
    EXPECT_FALSE(JsonValidator::isValid("[1.]"));
    EXPECT_FALSE(JsonValidator::isValid("[nan]"));
    EXPECT_FALSE(JsonValidator::isValid("{} {}"));
    EXPECT_FALSE(JsonValidator::isValid("[1"));
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

    EXPECT_TRUE(JsonValidator::isValid(trace)) << trace;
    EXPECT_EQ(trace.rfind(R"({"displayTimeUnit":"ms","traceEvents":[)", 0), 0u);
    EXPECT_NE(trace.find(R"("metadata":{"application":"tessera","backend":"pn-triangles","device":"Test GPU")"),
              std::string::npos);
    EXPECT_NE(trace.find(R"("width":1920,"height":0})"), std::string::npos);

    // Process and track names.
    EXPECT_NE(trace.find(R"({"name":"process_name","ph":"M","pid":1,"tid":0,"args":{"name":"tessera"}})"),
              std::string::npos);
    EXPECT_NE(trace.find(R"({"name":"thread_name","ph":"M","pid":1,"tid":1,"args":{"name":"CPU main"}})"),
              std::string::npos);
    EXPECT_NE(trace.find(R"("tid":3,"args":{"name":"CPU worker 2"}})"), std::string::npos);
    EXPECT_NE(trace.find(R"json("tid":1000000,"args":{"name":"GPU (Test GPU)"}})json"), std::string::npos);

    // Complete events in microseconds: 2,000,000 ns -> 2000, 1,500,000 ns -> 1500.
    EXPECT_NE(trace.find(R"({"name":"terrain","cat":"gpu","ph":"X","pid":1,"tid":1000000,"ts":2000,"dur":1500,)"
                         R"("args":{"frame":7,"inputAssemblyVertices":0,"inputAssemblyPrimitives":16,)"),
              std::string::npos);
    EXPECT_NE(trace.find(R"("tessEvaluationInvocations":300,"computeShaderInvocations":0,"triangles":100}})"),
              std::string::npos);
    EXPECT_NE(trace.find(R"("name":"decode","cat":"cpu","ph":"X","pid":1,"tid":3,"ts":1200,"dur":1.234,)"),
              std::string::npos);
    EXPECT_NE(trace.find(R"("name":"shadows \"cascade\"")"), std::string::npos);
    EXPECT_NE(trace.find(R"({"name":"blit","cat":"gpu","ph":"X","pid":1,"tid":1000000,"ts":3900,"dur":10,"args":{"frame":7}})"),
              std::string::npos);
    // Parent precedes child despite being recorded after it.
    EXPECT_LT(trace.find(R"("name":"parent")"), trace.find(R"("name":"child")"));

    // Recorded and derived counters.
    EXPECT_NE(trace.find(R"({"name":"memory MiB","ph":"C","pid":1,"ts":2500,"args":{"value":512.5}})"),
              std::string::npos);
    EXPECT_NE(trace.find(R"({"name":"triangles","ph":"C","pid":1,"ts":2000,"args":{"value":150}})"),
              std::string::npos);
    EXPECT_NE(trace.find(R"({"name":"tess-evaluation invocations","ph":"C","pid":1,"ts":2000,"args":{"value":500}})"),
              std::string::npos);
}

TEST(TraceWriter, RecordedFramesAppearOnTheirThreadTrack) {
    Profiler profiler;
    profiler.setEnabled(true);
    profiler.beginFrame(4);
    profiler.endFrame();
    std::string trace = makeChromeTrace(profiler, {});
    EXPECT_TRUE(JsonValidator::isValid(trace)) << trace;
    std::string tid = std::to_string(Profiler::currentThreadId() + 1);
    EXPECT_NE(trace.find(R"({"name":"frame","cat":"frame","ph":"X","pid":1,"tid":)" + tid), std::string::npos);
    EXPECT_NE(trace.find(R"("args":{"frame":4}})"), std::string::npos);
    EXPECT_EQ(trace.find("GPU"), std::string::npos); // No passes, no GPU track.
}

TEST(TraceWriter, EmptyProfilerGivesValidTrace) {
    Profiler profiler;
    EXPECT_TRUE(JsonValidator::isValid(makeChromeTrace(profiler, {})));
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

    EXPECT_TRUE(JsonValidator::isValid(report)) << report;
    EXPECT_NE(report.find(R"("scene": "canyon")"), std::string::npos);
    EXPECT_NE(report.find(R"("warmupFrames": 10)"), std::string::npos);
    EXPECT_NE(report.find("\"frames\": 2,\n  \"gpuFrame\""), std::string::npos);
    EXPECT_NE(report.find("\"name\": \"terrain\",\n      \"samples\": 2,\n      \"minMs\": 1.5,\n"
                          "      \"medianMs\": 2,\n      \"maxMs\": 2.5,\n      \"meanMs\": 2,"),
              std::string::npos)
        << report;
    EXPECT_NE(report.find("\"frameIndices\": [\n        7,\n        8\n      ],\n"
                          "      \"frameMs\": [\n        1.5,\n        2.5\n      ]"),
              std::string::npos)
        << report;
    EXPECT_NE(report.find("\"statsMedianFrame\": null"), std::string::npos); // blit, cpu frame.

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
