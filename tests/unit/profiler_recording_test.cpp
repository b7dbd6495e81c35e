#include "tessera/profiler/CpuScope.h"
#include "tessera/profiler/Profiler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <set>
#include <thread>
#include <vector>

namespace tessera::profiler {
namespace {

const CpuEvent* findCpu(const std::vector<CpuEvent>& events, const char* name) {
    auto it = std::find_if(events.begin(), events.end(),
                           [&](const CpuEvent& e) { return std::strcmp(e.name, name) == 0; });
    return it == events.end() ? nullptr : &*it;
}

TEST(Profiler, StartsDisabledAndRecordsNothingWhileDisabled) {
    Profiler profiler;
    EXPECT_FALSE(profiler.enabled());
    profiler.beginFrame(5);
    { CpuScope scope("ignored", profiler); }
    profiler.recordGpuPass({"pass", 5, 0, 10, std::nullopt});
    profiler.recordCounter({"memory", 5, 0, 1.0});
    profiler.endFrame();
    EXPECT_TRUE(profiler.cpuEvents().empty());
    EXPECT_TRUE(profiler.frameEvents().empty());
    EXPECT_TRUE(profiler.gpuPasses().empty());
    EXPECT_TRUE(profiler.counters().empty());
    // The frame index is still tracked, so enabling mid-run stamps correctly.
    EXPECT_EQ(profiler.currentFrame(), 5u);
}

TEST(Profiler, ClockIsMonotonicFromConstruction) {
    Profiler profiler;
    uint64_t a = profiler.nowNs();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    uint64_t b = profiler.nowNs();
    EXPECT_GE(b - a, 1'000'000u);
    EXPECT_LT(a, 1'000'000'000u); // Near zero: the epoch is construction.
}

TEST(Profiler, RecordsFramesOnTheCallingThread) {
    Profiler profiler;
    profiler.setEnabled(true);
    profiler.beginFrame(3);
    EXPECT_EQ(profiler.currentFrame(), 3u);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    profiler.endFrame();
    auto frames = profiler.frameEvents();
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_EQ(frames[0].frame, 3u);
    EXPECT_EQ(frames[0].threadId, Profiler::currentThreadId());
    EXPECT_GE(frames[0].durationNs, 1'000'000u);
}

TEST(CpuScope, TracksNestingDepthDurationsAndOrder) {
    Profiler profiler;
    profiler.setEnabled(true);
    profiler.beginFrame(9);
    {
        CpuScope outer("outer", profiler);
        {
            CpuScope inner("inner", profiler);
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            { CpuScope innermost("innermost", profiler); }
        }
        CpuScope sibling("sibling", profiler);
    }
    profiler.endFrame();

    auto events = profiler.cpuEvents();
    ASSERT_EQ(events.size(), 4u);
    // Recorded when they close: innermost first, outer last.
    EXPECT_STREQ(events[0].name, "innermost");
    EXPECT_STREQ(events[1].name, "inner");
    EXPECT_STREQ(events[2].name, "sibling");
    EXPECT_STREQ(events[3].name, "outer");

    const CpuEvent* outer = findCpu(events, "outer");
    const CpuEvent* inner = findCpu(events, "inner");
    const CpuEvent* innermost = findCpu(events, "innermost");
    const CpuEvent* sibling = findCpu(events, "sibling");
    EXPECT_EQ(outer->depth, 0u);
    EXPECT_EQ(inner->depth, 1u);
    EXPECT_EQ(innermost->depth, 2u);
    EXPECT_EQ(sibling->depth, 1u);
    for (const CpuEvent& e : events) {
        EXPECT_EQ(e.frame, 9u);
        EXPECT_EQ(e.threadId, Profiler::currentThreadId());
    }
    EXPECT_GE(inner->durationNs, 1'000'000u);
    // Children lie within their parents; siblings follow each other.
    EXPECT_GE(inner->startNs, outer->startNs);
    EXPECT_LE(inner->startNs + inner->durationNs, outer->startNs + outer->durationNs);
    EXPECT_GE(innermost->startNs, inner->startNs);
    EXPECT_LE(innermost->startNs + innermost->durationNs, inner->startNs + inner->durationNs);
    EXPECT_GE(sibling->startNs, inner->startNs + inner->durationNs);
}

TEST(CpuScope, DisabledScopeLeavesDepthUntouched) {
    Profiler profiler;
    {
        CpuScope off("off", profiler);
        profiler.setEnabled(true);
        CpuScope on("on", profiler);
    }
    auto events = profiler.cpuEvents();
    ASSERT_EQ(events.size(), 1u);
    EXPECT_STREQ(events[0].name, "on");
    EXPECT_EQ(events[0].depth, 0u);
}

TEST(CpuScope, MacroRecordsIntoTheGlobalProfiler) {
    Profiler& global = Profiler::global();
    global.clear();
    global.setEnabled(true);
    {
        TESSERA_CPU_SCOPE("macro a");
        TESSERA_CPU_SCOPE("macro b"); // Two in one block must not clash.
    }
    global.setEnabled(false);
    auto events = global.cpuEvents();
    global.clear();
    ASSERT_EQ(events.size(), 2u);
    EXPECT_STREQ(events[0].name, "macro b");
    EXPECT_EQ(events[0].depth, 1u);
    EXPECT_STREQ(events[1].name, "macro a");
}

TEST(CpuScope, ThreadsGetDistinctDenseIds) {
    Profiler profiler;
    profiler.setEnabled(true);
    { CpuScope scope("main", profiler); }
    constexpr int kThreads = 4;
    std::vector<std::thread> threads;
    for (int i = 0; i < kThreads; ++i) {
        threads.emplace_back([&profiler] {
            CpuScope outer("worker", profiler);
            CpuScope inner("worker inner", profiler);
        });
    }
    for (std::thread& t : threads) t.join();

    auto events = profiler.cpuEvents();
    ASSERT_EQ(events.size(), 1u + 2u * kThreads);
    std::set<uint32_t> workerIds;
    for (const CpuEvent& e : events) {
        if (std::strcmp(e.name, "worker") == 0) {
            workerIds.insert(e.threadId);
            EXPECT_EQ(e.depth, 0u); // Depth is per thread, not shared.
        }
        if (std::strcmp(e.name, "worker inner") == 0) {
            EXPECT_EQ(e.depth, 1u);
        }
    }
    EXPECT_EQ(workerIds.size(), static_cast<size_t>(kThreads));
    EXPECT_EQ(workerIds.count(Profiler::currentThreadId()), 0u);
    EXPECT_EQ(Profiler::currentThreadId(), findCpu(events, "main")->threadId);
}

TEST(Profiler, DiscardFramesBeforeDropsWarmUpRecords) {
    Profiler profiler;
    profiler.setEnabled(true);
    for (uint64_t frame = 0; frame < 5; ++frame) {
        profiler.beginFrame(frame);
        { CpuScope scope("work", profiler); }
        profiler.recordGpuPass({"pass", frame, frame * 100, 10, std::nullopt});
        profiler.recordCounter({"memory", frame, frame * 100, 1.0});
        profiler.endFrame();
    }
    profiler.discardFramesBefore(2);
    auto frameIndices = [](const auto& records) {
        std::vector<uint64_t> out;
        for (const auto& r : records) out.push_back(r.frame);
        return out;
    };
    const std::vector<uint64_t> kept = {2, 3, 4};
    EXPECT_EQ(frameIndices(profiler.cpuEvents()), kept);
    EXPECT_EQ(frameIndices(profiler.frameEvents()), kept);
    EXPECT_EQ(frameIndices(profiler.gpuPasses()), kept);
    EXPECT_EQ(frameIndices(profiler.counters()), kept);

    profiler.clear();
    EXPECT_TRUE(profiler.cpuEvents().empty());
    EXPECT_TRUE(profiler.frameEvents().empty());
    EXPECT_TRUE(profiler.gpuPasses().empty());
    EXPECT_TRUE(profiler.counters().empty());
}

} // namespace
} // namespace tessera::profiler
