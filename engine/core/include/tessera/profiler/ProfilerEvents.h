#pragma once
/// @file ProfilerEvents.h
/// The records a Profiler stores. All times are nanoseconds on the profiler's
/// timeline: a steady clock whose zero is the Profiler's construction
/// (Profiler::nowNs()).

#include "tessera/profiler/PipelineStatistics.h"

#include <cstdint>
#include <optional>
#include <string>

namespace tessera::profiler {

/// One CPU scope (normally made by CpuScope / TESSERA_CPU_SCOPE).
struct CpuEvent {
    /// Static string: only the pointer is stored, so it must outlive the
    /// profiler (a string literal).
    const char* name = nullptr;
    /// Dense per-OS-thread id from Profiler::currentThreadId(); 0 is the first
    /// thread that touched any profiler, normally the main thread.
    uint32_t threadId = 0;
    /// Profiler::currentFrame() when the scope opened.
    uint64_t frame = 0;
    uint64_t startNs = 0;
    uint64_t durationNs = 0;
    /// Number of CpuScopes already open on this thread when this one opened.
    uint32_t depth = 0;
};

/// One CPU frame, from Profiler::beginFrame() to Profiler::endFrame().
struct FrameEvent {
    uint64_t frame = 0;
    /// Thread that called beginFrame() (the thread whose track shows the frame).
    uint32_t threadId = 0;
    uint64_t startNs = 0;
    uint64_t durationNs = 0;
};

/// One GPU pass measured with timestamp queries (recorded by the Vulkan layer).
struct GpuPassEvent {
    std::string name;
    /// The frame whose command buffer held the pass (not the frame in which
    /// the results were read back).
    uint64_t frame = 0;
    /// Already mapped onto the profiler's CPU timeline by the caller.
    uint64_t startNs = 0;
    uint64_t durationNs = 0;
    /// Present when the pass ran under a pipeline-statistics query.
    std::optional<PipelineStatistics> stats;
};

/// One sample of a named value over time (memory in use, patches drawn, ...).
struct CounterSample {
    std::string name;
    uint64_t frame = 0;
    uint64_t timeNs = 0;
    double value = 0.0;
};

} // namespace tessera::profiler
