#include "tessera/profiler/BenchmarkReport.h"
#include "tessera/profiler/PipelineStatistics.h"

#include <gtest/gtest.h>

#include <chrono>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace tessera::profiler {
namespace {

constexpr uint64_t kMs = 1'000'000;

PipelineStatistics statsWithTriangles(uint64_t triangles) {
    PipelineStatistics s;
    s.clippingPrimitives = triangles;
    return s;
}

TEST(PipelineStatistics, TrianglesPreferClippedPrimitives) {
    PipelineStatistics s;
    s.inputAssemblyPrimitives = 10;
    s.clippingPrimitives = 40;
    EXPECT_EQ(trianglesOf(s), 40u);
    s.clippingPrimitives = 0; // No clipping counts, no tessellation: IA triangles.
    s.fragmentShaderInvocations = 500;
    EXPECT_EQ(trianglesOf(s), 10u);
    s.tessEvaluationInvocations = 99; // Tessellated: IA primitives are patches.
    EXPECT_EQ(trianglesOf(s), 0u);
    EXPECT_EQ(trianglesOf(PipelineStatistics{}), 0u);
}

TEST(PipelineStatistics, StreamOutPassesHaveNoTriangles) {
    // Rasterizer discard: points in, nothing reaches the clipper or fragments.
    PipelineStatistics s;
    s.inputAssemblyPrimitives = 1089;
    s.vertexShaderInvocations = 1089;
    EXPECT_EQ(trianglesOf(s), 0u);
}

TEST(PipelineStatistics, SumsEveryCounter) {
    PipelineStatistics a;
    int i = 1;
    forEachPipelineStatistic([&](const char*, uint64_t PipelineStatistics::*field) { a.*field = i++; });
    PipelineStatistics sum = a;
    sum += a;
    forEachPipelineStatistic([&](const char* name, uint64_t PipelineStatistics::*field) {
        EXPECT_EQ(sum.*field, 2 * (a.*field)) << name;
    });
    EXPECT_EQ(sum.computeShaderInvocations, 22u);
}

TEST(BenchmarkReport, SummarizesOddAndEvenSampleCounts) {
    Profiler profiler;
    profiler.setEnabled(true);
    // "odd": 3, 1, 2 ms over frames 0..2. "even": 4, 1, 3, 2 ms over frames 0..3.
    const std::vector<uint64_t> odd = {3, 1, 2};
    const std::vector<uint64_t> even = {4, 1, 3, 2};
    for (uint64_t frame = 0; frame < 4; ++frame) {
        if (frame < odd.size()) {
            profiler.recordGpuPass({"odd", frame, frame * 100 * kMs, odd[frame] * kMs,
                                    statsWithTriangles(odd[frame] * 1000)});
        }
        profiler.recordGpuPass({"even", frame, frame * 100 * kMs + 50 * kMs, even[frame] * kMs,
                                statsWithTriangles(even[frame] * 10)});
    }

    BenchmarkSummary summary = summarize(profiler);
    EXPECT_EQ(summary.frames, 4u);
    ASSERT_EQ(summary.passes.size(), 2u);

    const PassSummary& o = summary.passes[0]; // First-recorded order.
    EXPECT_EQ(o.name, "odd");
    EXPECT_EQ(o.samples, 3u);
    EXPECT_DOUBLE_EQ(o.minMs, 1.0);
    EXPECT_DOUBLE_EQ(o.medianMs, 2.0);
    EXPECT_DOUBLE_EQ(o.maxMs, 3.0);
    EXPECT_DOUBLE_EQ(o.meanMs, 2.0);
    ASSERT_TRUE(o.statsMedianFrame);
    EXPECT_EQ(o.statsMedianFrame->clippingPrimitives, 2000u); // The 2 ms frame.

    const PassSummary& e = summary.passes[1];
    EXPECT_EQ(e.name, "even");
    EXPECT_EQ(e.samples, 4u);
    EXPECT_DOUBLE_EQ(e.minMs, 1.0);
    EXPECT_DOUBLE_EQ(e.medianMs, 2.5); // Mean of the middle two.
    EXPECT_DOUBLE_EQ(e.maxMs, 4.0);
    EXPECT_DOUBLE_EQ(e.meanMs, 2.5);
    ASSERT_TRUE(e.statsMedianFrame);
    EXPECT_EQ(e.statsMedianFrame->clippingPrimitives, 20u); // Lower middle: the 2 ms frame.

    // GPU frame = sum of passes per frame: 7, 2, 5, 2 ms.
    EXPECT_EQ(summary.gpuFrame.name, "gpu frame");
    EXPECT_EQ(summary.gpuFrame.samples, 4u);
    EXPECT_DOUBLE_EQ(summary.gpuFrame.minMs, 2.0);
    EXPECT_DOUBLE_EQ(summary.gpuFrame.medianMs, 3.5);
    EXPECT_DOUBLE_EQ(summary.gpuFrame.maxMs, 7.0);
    EXPECT_DOUBLE_EQ(summary.gpuFrame.meanMs, 4.0);
    ASSERT_TRUE(summary.gpuFrame.statsMedianFrame);

    EXPECT_EQ(summary.cpuFrame.name, "cpu frame");
    EXPECT_EQ(summary.cpuFrame.samples, 0u);
    EXPECT_DOUBLE_EQ(summary.cpuFrame.medianMs, 0.0);
    EXPECT_FALSE(summary.cpuFrame.statsMedianFrame);
}

TEST(BenchmarkReport, SumsRepeatedPassNamesWithinAFrame) {
    Profiler profiler;
    profiler.setEnabled(true);
    profiler.recordGpuPass({"cascade", 1, 0, 1 * kMs, statsWithTriangles(5)});
    profiler.recordGpuPass({"cascade", 1, 2 * kMs, 2 * kMs, statsWithTriangles(7)});
    BenchmarkSummary summary = summarize(profiler);
    ASSERT_EQ(summary.passes.size(), 1u);
    EXPECT_EQ(summary.passes[0].samples, 1u);
    EXPECT_DOUBLE_EQ(summary.passes[0].medianMs, 3.0);
    EXPECT_EQ(summary.passes[0].statsMedianFrame->clippingPrimitives, 12u);
}

TEST(BenchmarkReport, CpuFrameComesFromBeginAndEndFrame) {
    Profiler profiler;
    profiler.setEnabled(true);
    for (uint64_t frame = 10; frame < 13; ++frame) {
        profiler.beginFrame(frame);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        profiler.endFrame();
    }
    BenchmarkSummary summary = summarize(profiler);
    EXPECT_EQ(summary.frames, 3u);
    EXPECT_EQ(summary.cpuFrame.samples, 3u);
    EXPECT_GE(summary.cpuFrame.minMs, 1.0);
    EXPECT_LE(summary.cpuFrame.minMs, summary.cpuFrame.medianMs);
    EXPECT_LE(summary.cpuFrame.medianMs, summary.cpuFrame.maxMs);
    EXPECT_EQ(summary.gpuFrame.samples, 0u);
    EXPECT_TRUE(summary.passes.empty());
}

TEST(BenchmarkReport, FormatsAlignedTable) {
    Profiler profiler;
    profiler.setEnabled(true);
    profiler.recordGpuPass({"terrain", 0, 0, 1'250'000, statsWithTriangles(123456)});
    profiler.recordGpuPass({"post", 0, 2 * kMs, 500'000, std::nullopt});
    std::string table = formatTable(summarize(profiler));

    std::istringstream lines(table);
    std::vector<std::string> rows;
    for (std::string line; std::getline(lines, line);) rows.push_back(line);
    ASSERT_EQ(rows.size(), 8u) << table;
    EXPECT_EQ(rows[0], "pass       min ms  median ms  max ms  triangles");
    EXPECT_EQ(rows[2], "terrain     1.250      1.250   1.250     123456");
    EXPECT_EQ(rows[3], "post        0.500      0.500   0.500          -");
    EXPECT_EQ(rows[5], "gpu frame   1.750      1.750   1.750     123456");
    EXPECT_EQ(rows[6], "cpu frame   0.000      0.000   0.000          -");
    EXPECT_EQ(rows[7], "1 frame");
    for (size_t i = 0; i + 1 < rows.size(); ++i) EXPECT_EQ(rows[i].size(), rows[0].size()) << i;
}

} // namespace
} // namespace tessera::profiler
