#include "tessera/profiler/CpuScope.h"

namespace tessera::profiler {
namespace {
// Per thread rather than per profiler: a thread has one call stack, and
// looking a profiler up per scope would cost more than the scope itself.
thread_local uint32_t sDepth = 0;
} // namespace

void CpuScope::open(Profiler& profiler) {
    mProfiler = &profiler;
    mDepth = sDepth++;
    mFrame = profiler.currentFrame();
    // Read the clock last so the scope's own bookkeeping is not timed.
    mStartNs = profiler.nowNs();
}

void CpuScope::close() {
    uint64_t endNs = mProfiler->nowNs();
    --sDepth;
    mProfiler->recordCpu(CpuEvent{mName, Profiler::currentThreadId(), mFrame, mStartNs,
                                  endNs - mStartNs, mDepth});
}

} // namespace tessera::profiler
