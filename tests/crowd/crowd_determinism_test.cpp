// Determinism: the same inputs give bit-identical agents after N steps,
// whatever the thread count, run after run.

#include "CrowdTestWorld.h"

#include <cstring>

namespace tessera::crowd::test {
namespace {

// A busy scenario: four goals, wanderers crossing, a crater halfway.
std::unique_ptr<Crowd> run(uint32_t threads, terrain::Terrain& ground) {
    std::vector<GoalGroup> goals = {{"a", Region::disc({40.0f, 40.0f}, 10.0f)},
                                    {"b", Region::disc({216.0f, 40.0f}, 10.0f)},
                                    {"c", Region::disc({40.0f, 216.0f}, 10.0f)},
                                    {"d", Region::disc({216.0f, 216.0f}, 10.0f)}};
    auto crowd = makeCrowd(ground, testSettings(threads), goals, {{Region::disc({128.0f, 128.0f}, 45.0f), 1500, 5}});
    if (!crowd) return nullptr;
    for (int s = 0; s < 240; ++s) {
        if (s == 120) ground.splat(glm::vec2(140.0f, 120.0f), 14.0f);
        crowd->step();
    }
    return crowd;
}

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expectIdentical(const Crowd& x, const Crowd& y, const char* what) {
    const CrowdAgents& a = x.agents();
    const CrowdAgents& b = y.agents();
    EXPECT_TRUE(sameBits(a.position, b.position)) << what;
    EXPECT_TRUE(sameBits(a.velocity, b.velocity)) << what;
    EXPECT_TRUE(sameBits(a.heading, b.heading)) << what;
    EXPECT_TRUE(sameBits(a.phase, b.phase)) << what;
    EXPECT_TRUE(sameBits(a.clip, b.clip)) << what;
    EXPECT_TRUE(sameBits(a.goalGroup, b.goalGroup)) << what;
    for (uint32_t g = 0; g < x.goals().size(); ++g)
        EXPECT_TRUE(std::memcmp(x.field(g).values().data(), y.field(g).values().data(),
                                x.field(g).values().size_bytes()) == 0)
            << what << ": field " << g;
}

TEST(CrowdDeterminism, SameStateWithOneTwoAndEightThreads) {
    auto ground1 = flatTerrain(257, 1.0f), ground2 = flatTerrain(257, 1.0f), ground8 = flatTerrain(257, 1.0f);
    auto one = run(1, *ground1), two = run(2, *ground2), eight = run(8, *ground8);
    ASSERT_TRUE(one && two && eight);
    EXPECT_GT(one->stats().walking, 0u);
    EXPECT_EQ(one->stats().activeHazards, 1u) << "the crater landed and is being avoided";
    expectIdentical(*one, *two, "1 vs 2 threads");
    expectIdentical(*one, *eight, "1 vs 8 threads");
}

TEST(CrowdDeterminism, SameStateRunAfterRun) {
    auto groundA = flatTerrain(257, 1.0f), groundB = flatTerrain(257, 1.0f);
    auto a = run(0, *groundA), b = run(0, *groundB);
    ASSERT_TRUE(a && b);
    expectIdentical(*a, *b, "two runs");
}

} // namespace
} // namespace tessera::crowd::test
