#include "tessera/profiler/Profiler.h"

#include <cassert>

namespace tessera::profiler {
namespace {
std::atomic<uint32_t> sNextThreadId{0};
} // namespace

Profiler::Profiler() : mEpoch(std::chrono::steady_clock::now()) {
    // Claim an id for the constructing thread so that the main thread, which
    // creates the global profiler first in practice, gets id 0 ("CPU main").
    currentThreadId();
}

Profiler& Profiler::global() {
    // Leaked on purpose: worker threads and static destructors may still open
    // scopes after main() returns.
    static Profiler* sGlobal = new Profiler();
    return *sGlobal;
}

uint32_t Profiler::currentThreadId() {
    thread_local const uint32_t sId = sNextThreadId.fetch_add(1, std::memory_order_relaxed);
    return sId;
}

void Profiler::setEnabled(bool enabled) { mEnabled.store(enabled, std::memory_order_relaxed); }

void Profiler::beginFrame(uint64_t frameIndex) {
    uint64_t now = nowNs();
    mFrame.store(frameIndex, std::memory_order_relaxed);
    std::lock_guard lock(mMutex);
    assert(!mInFrame && "beginFrame() while a frame is open");
    mInFrame = true;
    mOpenFrame = FrameEvent{frameIndex, currentThreadId(), now, 0};
}

void Profiler::endFrame() {
    uint64_t now = nowNs();
    std::lock_guard lock(mMutex);
    assert(mInFrame && "endFrame() without beginFrame()");
    if (!mInFrame || !enabled()) {
        mInFrame = false;
        return;
    }
    mInFrame = false;
    mOpenFrame.durationNs = now - mOpenFrame.startNs;
    mFrames.push_back(mOpenFrame);
}

uint64_t Profiler::nowNs() const {
    auto elapsed = std::chrono::steady_clock::now() - mEpoch;
    return static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count());
}

void Profiler::recordCpu(const CpuEvent& event) {
    if (!enabled()) return;
    std::lock_guard lock(mMutex);
    mCpuEvents.push_back(event);
}

void Profiler::recordGpuPass(GpuPassEvent event) {
    if (!enabled()) return;
    std::lock_guard lock(mMutex);
    mGpuPasses.push_back(std::move(event));
}

void Profiler::recordCounter(CounterSample sample) {
    if (!enabled()) return;
    std::lock_guard lock(mMutex);
    mCounters.push_back(std::move(sample));
}

std::vector<CpuEvent> Profiler::cpuEvents() const {
    std::lock_guard lock(mMutex);
    return mCpuEvents;
}

std::vector<FrameEvent> Profiler::frameEvents() const {
    std::lock_guard lock(mMutex);
    return mFrames;
}

std::vector<GpuPassEvent> Profiler::gpuPasses() const {
    std::lock_guard lock(mMutex);
    return mGpuPasses;
}

std::vector<CounterSample> Profiler::counters() const {
    std::lock_guard lock(mMutex);
    return mCounters;
}

void Profiler::clear() {
    std::lock_guard lock(mMutex);
    mCpuEvents.clear();
    mFrames.clear();
    mGpuPasses.clear();
    mCounters.clear();
}

void Profiler::discardFramesBefore(uint64_t frame) {
    auto before = [frame](const auto& record) { return record.frame < frame; };
    std::lock_guard lock(mMutex);
    std::erase_if(mCpuEvents, before);
    std::erase_if(mFrames, before);
    std::erase_if(mGpuPasses, before);
    std::erase_if(mCounters, before);
}

} // namespace tessera::profiler
