#pragma once
/// @file Profiler.h
/// Collects CPU scopes, CPU frames, GPU passes and counters, per frame.
///
/// The engine records into Profiler::global() through CpuScope
/// (TESSERA_CPU_SCOPE); the Vulkan layer adds GPU pass timings and pipeline
/// statistics with recordGpuPass(). Writers (TraceWriter.h, BenchmarkReport.h)
/// read copies of the records afterwards.
///
/// - **Disabled by default.** Records grow without bound while enabled, so
///   recording is opt-in (a trace or benchmark run calls setEnabled(true)).
///   While disabled every record call is a no-op and a CpuScope costs one
///   relaxed atomic load; beginFrame() still tracks the frame index.
/// - **Thread-safe.** Any thread may record at any time; one mutex guards the
///   records. A scope costs one uncontended lock and a push_back, which is
///   fine for the few thousand scopes per frame an engine records.
/// - **One timeline.** Times are steady-clock nanoseconds since construction
///   (nowNs()). GPU times must be mapped onto it by the caller.
///
/// @code
/// auto& profiler = Profiler::global();
/// profiler.setEnabled(true);
/// profiler.beginFrame(frameIndex);
/// { TESSERA_CPU_SCOPE("update crowd"); crowd.update(dt); }
/// profiler.endFrame();
/// @endcode

#include "tessera/profiler/ProfilerEvents.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <vector>

namespace tessera::profiler {

class Profiler {
public:
    /// A disabled profiler whose epoch (time 0) is now.
    Profiler();
    Profiler(const Profiler&) = delete;
    Profiler& operator=(const Profiler&) = delete;

    /// The process-wide instance CpuScope uses by default. It lives in
    /// tessera_core, so the host and every plugin share it. Never destroyed,
    /// so scopes running during static destruction stay valid.
    static Profiler& global();

    /// Small dense id of the calling OS thread, process-wide and stable for
    /// the thread's life: 0 for the first thread that asks (constructing a
    /// Profiler asks, so normally the main thread), then 1, 2, ... Ids are
    /// never reused, so profile from long-lived (pool) threads: a thread
    /// spawned per task gets a new trace track each time.
    static uint32_t currentThreadId();

    void setEnabled(bool enabled);
    bool enabled() const { return mEnabled.load(std::memory_order_relaxed); }

    /// Starts frame `frameIndex` on the calling thread: later scopes are
    /// stamped with it. Frames must not nest (asserts).
    void beginFrame(uint64_t frameIndex);
    /// Ends the frame begun by beginFrame() and records its FrameEvent (when
    /// enabled). Must follow a beginFrame() (asserts).
    void endFrame();
    /// Index passed to the latest beginFrame() (0 before the first).
    uint64_t currentFrame() const { return mFrame.load(std::memory_order_relaxed); }

    /// Asks the GPU profiler to count task and mesh shader invocations in
    /// the next frame it begins (a benchmark asks at each row's first
    /// measured frame). Those counters are off otherwise, but for every
    /// 16th frame: on NVIDIA (driver 580) a pipeline-statistics query with
    /// them makes the mesh stage about 7x slower, where the mesh primitives
    /// query costs nothing (docs/BACKENDS.md, "meshshader").
    void requestMeshInvocationCount() { mMeshInvocationRequest.store(true, std::memory_order_relaxed); }
    /// True once after requestMeshInvocationCount() (the GPU profiler asks).
    bool takeMeshInvocationRequest() { return mMeshInvocationRequest.exchange(false, std::memory_order_relaxed); }

    /// Steady-clock nanoseconds since this profiler was constructed.
    uint64_t nowNs() const;

    void recordCpu(const CpuEvent& event);
    void recordGpuPass(GpuPassEvent event);
    void recordCounter(CounterSample sample);

    /// Copies of the records, in recording order. CPU scopes are recorded
    /// when they close, so an inner scope precedes its outer one.
    std::vector<CpuEvent> cpuEvents() const;
    std::vector<FrameEvent> frameEvents() const;
    std::vector<GpuPassEvent> gpuPasses() const;
    std::vector<CounterSample> counters() const;

    /// Drops every record (the frame index and an open frame are kept).
    void clear();
    /// Drops every record whose frame index is below `frame` (warm-up frames).
    void discardFramesBefore(uint64_t frame);

private:
    const std::chrono::steady_clock::time_point mEpoch;
    std::atomic<bool> mEnabled{false};
    std::atomic<bool> mMeshInvocationRequest{false};
    std::atomic<uint64_t> mFrame{0};

    mutable std::mutex mMutex;
    bool mInFrame = false;
    FrameEvent mOpenFrame;
    std::vector<CpuEvent> mCpuEvents;
    std::vector<FrameEvent> mFrames;
    std::vector<GpuPassEvent> mGpuPasses;
    std::vector<CounterSample> mCounters;
};

} // namespace tessera::profiler
