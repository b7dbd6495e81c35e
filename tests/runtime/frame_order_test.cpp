// The frame's order on a CPU rasterizer (docs/BACKENDS.md, "Frame order on a
// CPU rasterizer"): the terrain's main-pass draw waits for the crowd's own
// passes (BasicTerrainBackend::drawTerrainInMainPass), so that lavapipe bins the
// crowd's tiers while it rasterizes the terrain instead of after. Read from
// the GPU passes the profiler records, in the order they were recorded; one
// backend per technique's terrain draw (r2vb draws it as streamout does).
#include "tessera/lod/LodPolicy.h"
#include "tessera/profiler/Profiler.h"
#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/SceneRun.h"
#include "SceneOptions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tessera::runtime {
namespace {

bool isTierDraw(const std::string& name) {
    return name == "crowd.near" || name == "crowd.middle" || name == "crowd.far" || name == "crowd.impostor";
}

class FrameOrder : public ::testing::TestWithParam<const char*> {};

TEST_P(FrameOrder, TheCrowdsOwnPassesComeBeforeTheTerrainsDraw) {
    profiler::Profiler& profiler = profiler::Profiler::global();
    profiler.clear();
    profiler.setEnabled(true);
    Options options = test::smallSceneOptions(GetParam(), "crowd");
    options.heightmap = test::smallTerrain();
    constexpr uint32_t kFrames = 2;
    auto created = SceneRun::create(options, kFrames);
    ASSERT_TRUE(created) << created.error().message;
    SceneRun& run = *created.value();
    if (run.session().deviceClass() != lod::DeviceClass::Cpu)
        GTEST_SKIP() << "a GPU keeps the order the frame is recorded in";
    for (uint32_t frame = 0; frame < kFrames; ++frame) ASSERT_TRUE(run.step(frame, false));
    (void)run.session().finish();
    profiler.setEnabled(false);

    std::vector<std::string> passes;
    for (const profiler::GpuPassEvent& e : profiler.gpuPasses())
        if (e.frame == kFrames - 1) passes.push_back(e.name);
    const auto terrain = std::find(passes.begin(), passes.end(), "terrain.adaptive");
    ASSERT_NE(terrain, passes.end()) << "no terrain draw in the last frame";
    size_t own = 0, tiers = 0;
    for (auto p = passes.begin(); p != passes.end(); ++p) {
        if (p->rfind("crowd.", 0) != 0) continue;
        if (isTierDraw(*p)) {
            ++tiers;
            EXPECT_GT(p, terrain) << *p << " (a tier's draw) before the terrain's";
        } else {
            ++own;
            EXPECT_LT(p, terrain) << *p << " (the crowd's own pass) after the terrain's draw";
        }
    }
    EXPECT_GT(own, 0u);
    EXPECT_EQ(tiers, 4u);
    EXPECT_EQ(validationMessages(), 0u);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, FrameOrder, ::testing::Values("streamout", "hulldomain", "meshshader"),
                         [](const auto& param) { return std::string(param.param); });

} // namespace
} // namespace tessera::runtime
