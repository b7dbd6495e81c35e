// Long runs of the crowd scene under a meteor shower (docs/RELIABILITY.md,
// "Soak"): after warm-up the heap in use, the resident set and the device
// memory stay flat, and the validation layer stays silent. The suite runs a
// short version; TESSERA_SOAK_FRAMES sets the length for the long runs
// (tools/soak.sh: 100,000 frames on the null backend, 10,000 on lavapipe).
#include "tessera/profiler/Profiler.h"
#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/SceneRun.h"
#include "ProcessMemory.h"
#include "SceneOptions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace tessera::runtime {
namespace {

using test::heapBytes;
using test::residentBytes;

uint32_t soakFrames(uint32_t shortRun) {
    if (const char* env = std::getenv("TESSERA_SOAK_FRAMES")) return std::max(40u, uint32_t(std::strtoul(env, nullptr, 10)));
    return shortRun;
}

struct Sample {
    uint64_t heap = 0, resident = 0, device = 0;
};

Sample sample(SceneRun& run) {
    run.session().finish();
    return {heapBytes(), residentBytes(), run.session().deviceBytes()};
}

/// Runs the crowd scene on `backend` for `frames` frames with a meteor every
/// 250 frames; checks memory after the first tenth (warm-up) against the end.
void soak(const std::string& backend, uint32_t agents, uint32_t frames) {
    profiler::Profiler::global().setEnabled(false);
    Options options = test::smallSceneOptions(backend, "crowd");
    options.agents = {agents};
    options.meteors = std::max(1u, frames / 250);
    auto created = SceneRun::create(options, frames);
    ASSERT_TRUE(created) << created.error().message;
    SceneRun& run = *created.value();
    const uint32_t warm = std::max(20u, frames / 10);
    Sample before;
    using Clock = std::chrono::steady_clock;
    // Step times of the first and the last quarter after warm-up: a drift
    // would show as the later mean well above the earlier.
    double early = 0.0, late = 0.0;
    const uint32_t quarter = (frames - warm) / 4;
    for (uint32_t frame = 0; frame < frames; ++frame) {
        const auto start = Clock::now();
        ASSERT_TRUE(run.step(frame, false)) << "frame " << frame;
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (frame >= warm && frame < warm + quarter) early += ms;
        if (frame >= frames - quarter) late += ms;
        if (frame + 1 == warm) before = sample(run);
    }
    const Sample after = sample(run);
    const double mib = 1.0 / 1048576.0;
    std::printf("[soak] %s, %u agents, %u frames (%u warm-up, %u meteors): heap %.2f -> %.2f MiB, resident %.1f -> "
                "%.1f MiB, device %.2f -> %.2f MiB, step %.2f -> %.2f ms (first and last quarter), validation "
                "messages %llu\n",
                backend.c_str(), agents, frames, warm, options.meteors, before.heap * mib, after.heap * mib,
                before.resident * mib, after.resident * mib, before.device * mib, after.device * mib,
                quarter ? early / quarter : 0.0, quarter ? late / quarter : 0.0,
                static_cast<unsigned long long>(validationMessages()));
    // Under 1% growth, with a megabyte's slack for the allocator's and the
    // driver's rounding (a leak of a scene's worth per frame is far beyond).
    EXPECT_LE(after.heap, before.heap + before.heap / 100 + (1u << 20)) << "the heap grew";
    EXPECT_LE(after.resident, before.resident + before.resident / 100 + (4u << 20)) << "the resident set grew";
    EXPECT_EQ(after.device, before.device) << "device memory grew";
    EXPECT_EQ(validationMessages(), 0u);
}

TEST(FrameSoak, NullBackendCrowdUnderMeteorsFlat) { soak("null", 2000, soakFrames(3000)); }

TEST(FrameSoak, LavapipeCrowdUnderMeteorsFlat) { soak("hulldomain", 256, soakFrames(300)); }

} // namespace
} // namespace tessera::runtime
