// The crowd scene runs each simulation step beside the drawing of the frame
// before it (SimulatedCrowd::update starts it on its own thread, World::update
// waits for it): the steps must be the ones the scene took before, one after
// the other on the frame's thread, bit for bit; the frame must show and
// report the same (docs/CROWD.md 2, "Determinism and threads").
#include "SceneOptions.h"

#include "tessera/runtime/SceneRun.h"
#include "tessera/runtime/SimulatedCrowd.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace tessera::runtime {
namespace {

constexpr uint32_t kFrames = 24;

std::unique_ptr<SceneRun> crowdScene(bool ahead) {
    Options options = test::smallSceneOptions("null", "crowd");
    options.heightmap = test::smallTerrain();
    options.agents = {300};
    // No craters: a step running ahead sees a crater one step later, which
    // is the one difference allowed.
    options.meteors = 0;
    auto created = SceneRun::create(options, kFrames + 1);
    EXPECT_TRUE(created) << created.error().message;
    if (!created) return nullptr;
    created.value()->world().simulatedCrowd()->setStepAhead(ahead);
    return std::move(created.value());
}

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(CrowdStepAhead, TakesTheSameStepsAsTheFramesThreadAndShowsTheSame) {
    auto ahead = crowdScene(true);
    auto inline_ = crowdScene(false);
    ASSERT_TRUE(ahead && inline_);
    SimulatedCrowd& a = *ahead->world().simulatedCrowd();
    SimulatedCrowd& b = *inline_->world().simulatedCrowd();
    for (uint32_t frame = 0; frame < kFrames; ++frame) {
        ASSERT_TRUE(ahead->step(frame, false));
        ASSERT_TRUE(inline_->step(frame, false));
        // Each frame draws the same instances.
        const auto ia = a.instancedCrowd()->instances(), ib = b.instancedCrowd()->instances();
        ASSERT_EQ(ia.size(), ib.size());
        ASSERT_EQ(std::memcmp(ia.data(), ib.data(), ia.size_bytes()), 0) << "frame " << frame;
    }
    // What the run reports is what it showed: kFrames steps on both (all
    // but the step's mean time, a timing).
    const auto shown = [](const std::string& line) { return line.substr(0, line.find("; a step took")); };
    EXPECT_EQ(shown(a.summary()), shown(b.summary()));
    EXPECT_NE(shown(a.summary()).find(std::to_string(kFrames) + " steps"), std::string::npos) << a.summary();
    // The step started during the last frame has run: one step further.
    EXPECT_EQ(a.crowd().stepCount(), kFrames + 1u);
    ASSERT_TRUE(inline_->step(kFrames, false));
    const crowd::CrowdAgents& x = a.crowd().agents();
    const crowd::CrowdAgents& y = b.crowd().agents();
    EXPECT_EQ(b.crowd().stepCount(), kFrames + 1u);
    EXPECT_TRUE(sameBytes(x.id, y.id));
    EXPECT_TRUE(sameBytes(x.position, y.position));
    EXPECT_TRUE(sameBytes(x.velocity, y.velocity));
    EXPECT_TRUE(sameBytes(x.heading, y.heading));
    EXPECT_TRUE(sameBytes(x.phase, y.phase));
}

} // namespace
} // namespace tessera::runtime
