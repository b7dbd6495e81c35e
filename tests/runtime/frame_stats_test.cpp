// The overlay's frame statistics: the newest resolved GPU frame wins, its
// passes keep their order, pipeline statistics add up, history is bounded.
#include "window/FrameStats.h"

#include <gtest/gtest.h>

namespace tessera::runtime {
namespace {

profiler::GpuPassEvent pass(const char* name, uint64_t frame, double ms, uint64_t fragments = 0) {
    profiler::GpuPassEvent e;
    e.name = name;
    e.frame = frame;
    e.durationNs = uint64_t(ms * 1e6);
    if (fragments) {
        e.stats = profiler::PipelineStatistics{};
        e.stats->fragmentShaderInvocations = fragments;
    }
    return e;
}

TEST(FrameStats, TakesTheNewestFrameAndSumsItsPasses) {
    FrameStats stats;
    const std::vector<profiler::GpuPassEvent> passes = {pass("terrain", 4, 1.0, 10), pass("overlay", 4, 0.25),
                                                        pass("terrain", 5, 2.0, 30), pass("crowd.near", 5, 0.5, 12)};
    stats.addGpuPasses(passes);
    EXPECT_EQ(stats.gpuFrame(), 5u);
    ASSERT_EQ(stats.passes().size(), 2u);
    EXPECT_EQ(stats.passes()[0].name, "terrain");
    EXPECT_EQ(stats.passes()[1].name, "crowd.near");
    EXPECT_NEAR(stats.gpuMs(), 2.5f, 1e-5f);
    ASSERT_TRUE(stats.hasStatistics());
    EXPECT_EQ(stats.statistics().fragmentShaderInvocations, 42u);
    // The same frame again (the profiler still holds it) adds no history.
    stats.addGpuPasses(passes);
    EXPECT_EQ(stats.gpuHistory().size(), 1u);
}

TEST(FrameStats, HistoryIsBounded) {
    FrameStats stats;
    for (int i = 0; i < 1000; ++i) stats.addCpuFrame(float(i));
    EXPECT_EQ(stats.cpuHistory().size(), FrameStats::kHistory);
    EXPECT_FLOAT_EQ(stats.cpuMs(), 999.0f);
    stats.addGpuPasses({});
    EXPECT_EQ(stats.gpuMs(), 0.0f);
}

} // namespace
} // namespace tessera::runtime
