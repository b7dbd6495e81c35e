// Out of device memory (docs/RELIABILITY.md, "Exhaustion"): any allocation
// of a scene can be the one that does not fit, at load time or in a frame.
// Each must end the run with OutOfDeviceMemory naming it, release
// everything made so far as the stack unwinds, and leave the validation
// layer's object tracking with nothing to report when the device is
// destroyed. Two ways to run out: the cap a user gives (--device-memory-cap,
// Device::setMemoryCap) and the fault injection that fails allocation
// number k (Device::failAllocation), which reaches the allocations a cap
// cannot (those made after the load's staging peak, below it).
//
// The suite samples allocations per scene and backend; TESSERA_OOM_WALK=full
// fails every one in turn (tools/oom_walk.sh; the figures in RELIABILITY.md).
#include "tessera/core/OutOfDeviceMemory.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/SceneRun.h"
#include "SceneOptions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tessera::runtime {
namespace {

constexpr uint32_t kFrames = 3;

bool fullWalk() {
    const char* env = std::getenv("TESSERA_OOM_WALK");
    return env && std::strcmp(env, "full") == 0;
}

Options sceneOptions(const std::string& backend, const std::string& scene) {
    Options options = test::smallSceneOptions(backend, scene);
    // The sample on the 2 km crop: the same allocations, and each run no
    // longer spends two thirds of its time solving the crowd's fields over
    // 8 km. The full walk keeps the content terrain (RELIABILITY.md's figures).
    if (!fullWalk()) options.heightmap = test::smallTerrain();
    if (scene == "crowd") options.agents = {128};
    else {
        // A Catmull-Clark control mesh with holes nobody here made, beside two creatures.
        options.surfaces = {std::string(TESSERA_TESTDATA_DIR) + "/osd_shapes/catmark_hole_test1.obj"};
        options.crowd = 2;
    }
    return options;
}

/// What an uncapped run allocates.
struct Footprint {
    uint64_t peak = 0;        ///< device memory at its highest while the scene is made
    uint64_t allocations = 0; ///< allocations the scene's creation makes
    uint64_t total = 0;       ///< allocations the whole run makes, frames included
};

Footprint footprint(const Options& options) {
    Footprint f;
    auto run = SceneRun::create(options, kFrames);
    if (!run) {
        ADD_FAILURE() << run.error().message;
        return f;
    }
    RenderSession& session = run.value()->session();
    f.peak = session.peakDeviceBytes();
    f.allocations = session.deviceAllocations();
    for (uint32_t frame = 0; frame < kFrames; ++frame) run.value()->step(frame, frame + 1 == kFrames);
    (void)run.value()->session().finish();
    f.total = session.deviceAllocations();
    return f;
}

/// How one run that ran out ended.
struct Outcome {
    bool outOfMemory = false;
    bool inFrame = false;   ///< thrown by a frame rather than by SceneRun::create
    std::string allocation; ///< the allocation that did not fit
};

/// Runs the scene with `options` (a cap or a failing allocation) and checks
/// it ends in OutOfDeviceMemory with nothing left behind. With `squeeze`,
/// once the scene is made the cap drops to exactly what it holds, so the
/// first allocation a frame makes fails.
Outcome runOutOfMemory(const Options& options, bool squeeze, const std::string& what) {
    Outcome outcome;
    const uint64_t messagesBefore = validationMessages();
    bool created = false;
    try {
        auto run = SceneRun::create(options, kFrames);
        if (!run) {
            ADD_FAILURE() << what << ": " << run.error().message;
            return outcome;
        }
        created = true;
        RenderSession& session = run.value()->session();
        if (squeeze) session.setDeviceMemoryCap(session.deviceBytes());
        for (uint32_t frame = 0; frame < kFrames; ++frame) run.value()->step(frame, frame + 1 == kFrames);
        (void)run.value()->session().finish();
    } catch (const OutOfDeviceMemory& e) {
        outcome.outOfMemory = true;
        outcome.inFrame = created;
        outcome.allocation = e.allocation();
        if (e.capBytes() && !created) {
            EXPECT_EQ(e.capBytes(), options.deviceMemoryCap);
            EXPECT_GT(e.inUseBytes() + e.requestedBytes(), e.capBytes()) << e.what();
        }
        EXPECT_NE(std::string(e.what()).find("out of device memory: " + e.allocation()), std::string::npos)
            << e.what();
    }
    EXPECT_TRUE(outcome.outOfMemory) << what << ": the run did not run out";
    // By now the scene, the backend and the device are gone: anything not
    // released would have been reported by vkDestroyDevice's object tracking.
    EXPECT_EQ(validationMessages(), messagesBefore) << what << " (failed at " << outcome.allocation << ")";
    return outcome;
}

/// Which runs a test makes: caps, and which allocations fail.
enum class Sample {
    Spread, ///< caps of one byte and half the load's peak, the cap of the made scene, allocations spread over the load
    Last,   ///< the load's last allocations (the scene's own, made after the terrain and the characters)
};

/// Indices of the allocations to fail: every one for the full walk, else
/// the sample's picks, then the first a frame makes.
std::vector<uint64_t> failingAllocations(const Footprint& f, Sample sample) {
    std::vector<uint64_t> picks;
    if (fullWalk()) {
        for (uint64_t i = 0; i < f.total; ++i) picks.push_back(i);
        return picks;
    }
    const uint64_t n = f.allocations;
    if (sample == Sample::Spread) picks = {n / 4, n / 2, 3 * n / 4, n - 1};
    else picks = {n - 3, n - 2, n - 1};
    if (f.total > n) picks.push_back(n);
    picks.erase(std::unique(picks.begin(), picks.end()), picks.end());
    return picks;
}

/// The scene on `backend` runs out of memory as `sample` says (the full walk:
/// under the caps, then at every allocation).
void exhaust(const std::string& backend, const std::string& scene, Sample sample) {
    profiler::Profiler::global().setEnabled(false);
    const Options base = sceneOptions(backend, scene);
    const Footprint f = footprint(base);
    ASSERT_GT(f.allocations, 0u);
    std::set<std::string> failedAt;
    uint32_t runs = 1, inFrame = 0;
    auto record = [&](const Outcome& outcome) {
        ++runs;
        failedAt.insert(outcome.allocation);
        inFrame += outcome.inFrame;
    };
    if (sample == Sample::Spread || fullWalk()) {
        for (uint64_t cap : {uint64_t(1), f.peak / 2}) {
            Options options = base;
            options.deviceMemoryCap = cap;
            record(runOutOfMemory(options, false, "cap " + std::to_string(cap)));
            if (::testing::Test::HasFailure()) return;
        }
        // Frames that allocate (the shadow casters' buffer, the read-back
        // buffer, r2vb's lazily made targets) fail under a cap of exactly
        // what the made scene holds.
        if (f.total > f.allocations) {
            const Outcome squeezed = runOutOfMemory(base, true, "cap of the made scene");
            EXPECT_TRUE(squeezed.inFrame) << "the squeezed run failed before its frames";
            record(squeezed);
        }
    }
    for (uint64_t index : failingAllocations(f, sample)) {
        Options options = base;
        options.failAllocation = index;
        record(runOutOfMemory(options, false, "allocation " + std::to_string(index)));
        if (::testing::Test::HasFailure()) return;
    }
    std::printf("[oom] %s, %s scene: %llu allocations to make it (peak %.2f MiB), %llu with %u frames; %u runs out "
                "of memory, %zu allocations failed (%u in a frame), validation messages 0\n",
                backend.c_str(), scene.c_str(), static_cast<unsigned long long>(f.allocations), f.peak / 1048576.0,
                static_cast<unsigned long long>(f.total), kFrames, runs - 1, failedAt.size(), inFrame);
    std::string names;
    for (const auto& name : failedAt) names += (names.empty() ? "" : ", ") + name;
    std::printf("[oom] failed at: %s\n", names.c_str());
}

/// Whether the device runs `backend` (meshshader needs mesh shaders).
bool deviceRuns(const std::string& backend) {
    return bool(SceneRun::create(test::smallSceneOptions(backend, "terrain"), 1));
}

TEST(DeviceMemoryExhaustion, MeshshaderCrowdScene) {
    if (!deviceRuns("meshshader")) GTEST_SKIP() << "the device cannot run meshshader";
    exhaust("meshshader", "crowd", Sample::Spread);
}
TEST(DeviceMemoryExhaustion, HulldomainCrowdScene) { exhaust("hulldomain", "crowd", Sample::Spread); }
TEST(DeviceMemoryExhaustion, R2vbCrowdScene) { exhaust("r2vb", "crowd", Sample::Spread); }
TEST(DeviceMemoryExhaustion, StreamoutCrowdScene) { exhaust("streamout", "crowd", Sample::Spread); }
TEST(DeviceMemoryExhaustion, HulldomainSubdivSurface) { exhaust("hulldomain", "characters", Sample::Last); }
TEST(DeviceMemoryExhaustion, R2vbSubdivSurface) { exhaust("r2vb", "characters", Sample::Last); }
TEST(DeviceMemoryExhaustion, StreamoutSubdivSurface) { exhaust("streamout", "characters", Sample::Last); }

} // namespace
} // namespace tessera::runtime
