// Switching backends at run time, 1,000 times in one process, as the demo's
// overlay does: the scene is re-created on each new backend, memory stays
// flat (host and device) and the validation layer stays silent.
#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/SceneRun.h"
#include "tessera/profiler/Profiler.h"
#include "ProcessMemory.h"
#include "SceneOptions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace tessera::runtime {
namespace {

using test::heapBytes;

uint32_t soakSwitches() {
    // TESSERA_SOAK_SWITCHES lets a longer soak run by hand; CI runs 1,000.
    if (const char* env = std::getenv("TESSERA_SOAK_SWITCHES")) return uint32_t(std::strtoul(env, nullptr, 10));
    return 1000;
}

Options soakOptions(const std::string& backend, const std::string& scene) {
    // The crowd scene exercises every kind of GPU object a backend makes
    // (terrain, characters, the instanced crowd), the terrain scene the
    // terrain's; small, so the soak is about the switches and not the
    // rasterizer. On the 2 km crop: every switch re-creates the terrain on
    // the next backend, which over 8 km was two thirds of the soak's time.
    Options options = test::smallSceneOptions(backend, scene);
    options.validation = true;
    options.heightmap = test::smallTerrain();
    return options;
}

struct SoakFigures {
    uint64_t hostBefore = 0, hostAfter = 0, deviceBefore = 0, deviceAfter = 0;
};

/// Switches `switches` times through `cycle`, drawing a frame after each
/// switch; the baseline is taken after the first full cycles, once every
/// backend's plugin is loaded and the allocator has settled. Whole cycles,
/// so the baseline and the end (with `switches` a multiple of the cycle)
/// are on the same backend, whose device memory they compare.
SoakFigures soak(SceneRun& run, const std::vector<std::string>& cycle, uint32_t switches) {
    SoakFigures figures;
    const uint32_t size = uint32_t(cycle.size());
    const uint32_t warm = size * std::clamp(switches / 2 / size, 1u, 4u);
    uint32_t frame = 0;
    for (uint32_t i = 0; i < switches; ++i) {
        const std::string& next = cycle[(i + 1) % cycle.size()];
        Status ok = run.switchBackend(next);
        EXPECT_TRUE(ok) << "switch " << i << " to " << next << ": " << (ok ? "" : ok.error().message);
        if (!ok) break;
        EXPECT_EQ(run.session().capabilities().name, next);
        EXPECT_TRUE(run.step(frame++, false));
        if (i + 1 == warm) {
            run.session().finish();
            figures.hostBefore = heapBytes();
            figures.deviceBefore = run.session().deviceBytes();
        }
    }
    run.session().finish();
    figures.hostAfter = heapBytes();
    figures.deviceAfter = run.session().deviceBytes();
    std::printf("%u switches: host %.1f -> %.1f MiB, device %.1f -> %.1f MiB, validation messages %llu\n", switches,
                figures.hostBefore / 1048576.0, figures.hostAfter / 1048576.0, figures.deviceBefore / 1048576.0,
                figures.deviceAfter / 1048576.0, static_cast<unsigned long long>(validationMessages()));
    return figures;
}

/// Heap in use may move by a few allocations' worth (the validation layer's
/// own bookkeeping grows by about 4 KiB a switch even with every debug name
/// cleared, gpu::Device::clearName), never by a scene's worth per switch.
constexpr uint64_t kHostSlackBytes = 8ull << 20;

TEST(BackendSwitch, NullBackendThousandTimesFlat) {
    profiler::Profiler::global().setEnabled(false);
    auto created = SceneRun::create(soakOptions("null", "crowd"), 1u << 20);
    ASSERT_TRUE(created) << created.error().message;
    // Not parked: every switch destroys the backend and makes a new one.
    created.value()->session().setParkBackends(false);
    const SoakFigures f = soak(*created.value(), {"null"}, soakSwitches());
    EXPECT_LE(f.hostAfter, f.hostBefore + kHostSlackBytes);
    EXPECT_EQ(validationMessages(), 0u);
}

/// The GPU backends, meshshader where the device has mesh shaders (asked
/// once, by making its scene).
const std::vector<std::string>& gpuCycle() {
    static const std::vector<std::string> cycle = [] {
        std::vector<std::string> backends = {"r2vb", "streamout", "hulldomain"};
        if (SceneRun::create(soakOptions("meshshader", "terrain"), 1)) backends.push_back("meshshader");
        return backends;
    }();
    return cycle;
}

TEST(BackendSwitch, LavapipeThousandTimesFlat) {
    // As the window switches: the backends switched away from stay
    // initialised (parked), each switch re-creates the scene on the next.
    profiler::Profiler::global().setEnabled(false);
    auto created = SceneRun::create(soakOptions("r2vb", "terrain"), 1u << 20);
    ASSERT_TRUE(created) << created.error().message;
    const SoakFigures f = soak(*created.value(), gpuCycle(), soakSwitches());
    EXPECT_EQ(f.deviceAfter, f.deviceBefore) << "device memory grew over the soak";
    EXPECT_LE(f.hostAfter, f.hostBefore + kHostSlackBytes);
    EXPECT_EQ(validationMessages(), 0u);
}

TEST(BackendSwitch, LavapipeCrowdSceneFlat) {
    // The crowd scene re-creates characters and the instanced crowd too
    // (about half a second a switch on lavapipe under validation).
    profiler::Profiler::global().setEnabled(false);
    auto created = SceneRun::create(soakOptions("r2vb", "crowd"), 1u << 20);
    ASSERT_TRUE(created) << created.error().message;
    const SoakFigures f = soak(*created.value(), gpuCycle(), 60);
    EXPECT_EQ(f.deviceAfter, f.deviceBefore) << "device memory grew over the switches";
    EXPECT_LE(f.hostAfter, f.hostBefore + kHostSlackBytes);
    EXPECT_EQ(validationMessages(), 0u);
}

TEST(BackendSwitch, LavapipeFullReinitializationFlat) {
    // Not parked: each switch shuts a backend down and initialises the next
    // from nothing (every pipeline compiled again, seconds each on lavapipe,
    // hence fewer switches).
    profiler::Profiler::global().setEnabled(false);
    auto created = SceneRun::create(soakOptions("r2vb", "crowd"), 1u << 20);
    ASSERT_TRUE(created) << created.error().message;
    created.value()->session().setParkBackends(false);
    const SoakFigures f = soak(*created.value(), gpuCycle(), 12);
    EXPECT_EQ(f.deviceAfter, f.deviceBefore) << "device memory grew over the switches";
    EXPECT_LE(f.hostAfter, f.hostBefore + kHostSlackBytes);
    EXPECT_EQ(validationMessages(), 0u);
}

TEST(BackendSwitch, RefusalsLeaveTheSceneDrawing) {
    auto created = SceneRun::create(soakOptions("hulldomain", "crowd"), 100);
    ASSERT_TRUE(created) << created.error().message;
    SceneRun& run = *created.value();
    Status missing = run.switchBackend("nosuch");
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("nosuch"), std::string::npos) << missing.error().message;
    Status null = run.switchBackend("null");
    ASSERT_FALSE(null);
    EXPECT_NE(null.error().message.find("null"), std::string::npos) << null.error().message;
    EXPECT_EQ(run.session().capabilities().name, "hulldomain");
    EXPECT_TRUE(run.step(0, true));
    EXPECT_FALSE(run.session().finish().empty());
    EXPECT_EQ(validationMessages(), 0u);
}

TEST(BackendSwitch, ReloadWorldWithAnotherCrowd) {
    // The window's crowd-size control: a new world on the same backend.
    auto created = SceneRun::create(soakOptions("streamout", "crowd"), 100);
    ASSERT_TRUE(created) << created.error().message;
    SceneRun& run = *created.value();
    EXPECT_TRUE(run.step(0, false));
    ASSERT_NE(run.world().simulatedCrowd(), nullptr);
    EXPECT_EQ(run.world().simulatedCrowd()->instanceCapacity(), 64u);
    Options bigger = run.options();
    bigger.agents = {200};
    Status ok = run.reloadWorld(bigger);
    ASSERT_TRUE(ok) << ok.error().message;
    EXPECT_EQ(run.world().simulatedCrowd()->instanceCapacity(), 200u);
    EXPECT_NE(run.instancedCrowd(), nullptr) << "the new crowd is drawn instanced on the GPU again";
    EXPECT_TRUE(run.step(1, true));
    EXPECT_FALSE(run.session().finish().empty());
    EXPECT_EQ(validationMessages(), 0u);
}

} // namespace
} // namespace tessera::runtime
