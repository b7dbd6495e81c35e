// Animation state: walk or idle from speed, the walk phase following the
// ground covered so feet do not slide.

#include "CrowdTestWorld.h"
#include "tessera/character/StrideLength.h"
#include "tessera/terrain/CraterSplat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tessera::crowd::test {
namespace {

// A walk clip with planted feet: hips 1 m up, each foot on the ground for
// 60% of a 1.1 s cycle sliding back under the hips from +0.4 m to -0.4 m,
// then swinging forward, lifting 0.1 m; the right foot half a cycle behind.
// Its stride is 0.8 m / (0.6 x 1.1 s) x 1.1 s = 1.333 m per cycle.
character::CharacterAsset plantedWalker() {
    constexpr float kCycle = 1.1f, kStance = 0.6f, kHalfStep = 0.4f, kLift = 0.1f;
    character::CharacterAsset a;
    a.name = "walker";
    auto node = [](const char* name, int32_t parent, glm::vec3 t) {
        character::SkeletonNode n;
        n.name = name;
        n.parent = parent;
        n.rest.translation = t;
        return n;
    };
    a.skeleton.nodes = {node("root", -1, {0, 0, 0}),           node("hips", 0, {0, 1, 0}),
                        node("thigh_l", 1, {0.1f, -0.1f, 0}), node("foot_l", 2, {0, -0.8f, 0}),
                        node("thigh_r", 1, {-0.1f, -0.1f, 0}), node("foot_r", 4, {0, -0.8f, 0})};
    character::AnimationClip walk;
    walk.name = "walk";
    for (uint32_t foot : {3u, 5u}) {
        character::AnimationChannel c;
        c.node = foot;
        for (int k = 0; k <= 66; ++k) {
            const float t = kCycle * float(k) / 66.0f;
            float p = t / kCycle + (foot == 5u ? 0.5f : 0.0f);
            p -= std::floor(p);
            const float u = (p - kStance) / (1.0f - kStance);
            const glm::vec3 offset = p < kStance ? glm::vec3(0, 0, kHalfStep - 2.0f * kHalfStep * p / kStance)
                                                 : glm::vec3(0, kLift * std::sin(3.14159265f * u), -kHalfStep + 2.0f * kHalfStep * u);
            c.times.push_back(t);
            c.values.emplace_back(glm::vec3(0, -0.8f, 0) + offset, 0.0f);
        }
        walk.channels.push_back(c);
    }
    a.clips.push_back(walk);
    return a;
}

TEST(CrowdAnimation, FeetStayPlanted) {
    // The clip's own stride per cycle (measured from its feet) against the
    // ground each agent covers, with the demo's gait: the clip drawn at the
    // size that makes its stride the crowd's 0.63 m at a 0.4 m radius, and
    // speeds within 10% of the 0.57 m/s at which it plays at its own pace
    // (runtime::measureCrowdGait). 600 agents cross in the open, stop at
    // their goals, and run from an impact among them (1.8 times their
    // speed). A foot slides by |ground covered - stride x cycles played|, or
    // by all the ground covered while the idle clip plays; each agent's
    // slide must stay under 5% of its stride per stride walked.
    const character::CharacterAsset walker = plantedWalker();
    const character::StrideMeasure clip = character::measureStride(walker, 0);
    ASSERT_NEAR(clip.strideLength, 1.3333f, 0.03f);
    constexpr float kCrowdStride = 0.63f; // the demo's "crowd gait: 0.63 m per walk cycle at radius 0.40 m"
    const float drawScale = kCrowdStride / clip.strideLength;
    auto ground = flatTerrain(161, 1.0f);
    CrowdSettings settings = testSettings();
    settings.walkStrideLength = clip.strideLength * drawScale;
    settings.walkCycleSeconds = walker.clips[0].duration();
    const float natural = settings.walkStrideLength / walker.clips[0].duration();
    const std::vector<GoalGroup> goals = {
        {"east", Region::rect({95.0f, 40.0f}, {150.0f, 120.0f}), ArrivalPolicy::Stay},
        {"west", Region::rect({10.0f, 40.0f}, {65.0f, 120.0f}), ArrivalPolicy::Stay}};
    std::vector<SpawnPattern> spawns = {{Region::rect({40.0f, 55.0f}, {70.0f, 105.0f}), 300, 3, 0},
                                        {Region::rect({90.0f, 55.0f}, {120.0f, 105.0f}), 300, 4, 1}};
    for (SpawnPattern& spawn : spawns) {
        spawn.radiusMin = 0.38f, spawn.radiusMax = 0.42f;
        spawn.speedMin = 0.9f * natural, spawn.speedMax = 1.1f * natural;
    }
    auto crowd = makeCrowd(*ground, settings, goals, spawns);
    ASSERT_TRUE(crowd);
    const CrowdAgents& a = crowd->agents();
    const size_t n = a.size();
    std::vector<glm::vec2> where(n);
    std::vector<float> phase(n);
    std::vector<AgentClip> clipOf(n);
    std::vector<double> slide(n, 0.0), cycles(n, 0.0);
    for (size_t i = 0; i < n; ++i) where[a.id[i]] = xz(a.position[i]), phase[a.id[i]] = a.phase[i], clipOf[a.id[i]] = a.clip[i];
    const float dt = settings.timeStep;
    for (int s = 0; s < int(80.0f / dt); ++s) {
        if (s == int(30.0f / dt)) ground->splat(glm::vec2(80.0f, 80.0f), 12.0f, terrain::CraterProfile{1.0f, 0.3f, 0.7f});
        crowd->step();
        for (size_t i = 0; i < n; ++i) {
            const uint32_t id = a.id[i];
            const float stride = settings.walkStrideLength * a.radius[i] / settings.strideRadius;
            const float covered = glm::distance(xz(a.position[i]), where[id]);
            float played = 0.0f;
            if (a.clip[i] == AgentClip::Walk && clipOf[id] == AgentClip::Walk) {
                played = a.phase[i] - phase[id];
                played -= std::floor(played);
            }
            slide[id] += std::abs(covered - stride * played) / stride;
            cycles[id] += played;
            where[id] = xz(a.position[i]), phase[id] = a.phase[i], clipOf[id] = a.clip[i];
        }
    }
    double worst = 0.0, total = 0.0, walked = 0.0;
    for (size_t id = 0; id < n; ++id) {
        worst = std::max(worst, slide[id] / std::max(cycles[id], 1.0));
        total += slide[id], walked += cycles[id];
    }
    std::printf("foot slide: %.4f of a stride per stride walked over the crowd, worst agent %.4f (%.0f strides)\n",
                total / walked, worst, walked);
    EXPECT_LT(worst, 0.05);
    EXPECT_GT(crowd->stats().staying, n / 10) << "some should have stopped at their goals too";
}

/// Walk cycles each agent (by id) plays over `steps` steps after 60 to get
/// going, every agent walking throughout, and where each started (`from`).
struct CyclesWalked {
    std::vector<glm::vec2> from;
    std::vector<double> cycles;
};
CyclesWalked walkCycles(Crowd& crowd, int steps) {
    const CrowdAgents& a = crowd.agents();
    for (int s = 0; s < 60; ++s) crowd.step(); // get going
    // Per agent id (indices change as the crowd re-sorts itself).
    CyclesWalked walked{std::vector<glm::vec2>(a.size()), std::vector<double>(a.size(), 0.0)};
    std::vector<float> phase(a.size());
    for (size_t i = 0; i < a.size(); ++i) walked.from[a.id[i]] = xz(a.position[i]), phase[a.id[i]] = a.phase[i];
    for (int s = 0; s < steps; ++s) {
        crowd.step();
        for (size_t i = 0; i < a.size(); ++i) {
            const uint32_t id = a.id[i];
            EXPECT_EQ(a.clip[i], AgentClip::Walk) << "agent " << id;
            EXPECT_GE(a.phase[i], 0.0f);
            EXPECT_LT(a.phase[i], 1.0f);
            float advance = a.phase[i] - phase[id];
            if (advance < 0.0f) advance += 1.0f;
            walked.cycles[id] += advance;
            phase[id] = a.phase[i];
        }
    }
    return walked;
}

TEST(CrowdAnimation, WalkPhaseFollowsTheGroundCovered) {
    auto ground = flatTerrain(257, 1.0f);
    CrowdSettings settings = testSettings();
    settings.walkStrideLength = 1.3f;
    settings.strideRadius = 0.4f;
    // Agents far apart walking a long way: nobody in anybody's way.
    SpawnPattern spawn{Region::rect({20.0f, 20.0f}, {40.0f, 236.0f}), 30, 6, 0, 0.3f, 0.5f};
    auto crowd = makeCrowd(*ground, settings, {{"east", Region::rect({230.0f, 0.0f}, {256.0f, 256.0f})}}, {spawn});
    ASSERT_TRUE(crowd);
    const CyclesWalked walked = walkCycles(*crowd, 150);
    // Cycles times this agent's stride is the distance walked.
    const CrowdAgents& a = crowd->agents();
    for (size_t i = 0; i < a.size(); ++i) {
        const uint32_t id = a.id[i];
        const float stride = settings.walkStrideLength * a.radius[i] / settings.strideRadius;
        const float distance = glm::distance(walked.from[id], xz(a.position[i]));
        EXPECT_NEAR(float(walked.cycles[id]) * stride, distance, 0.02f * distance) << "agent " << id;
    }
}

TEST(CrowdAnimation, EachKindOfWalkerWalksItsOwnStride) {
    // Two kinds of walker (CrowdSettings::kinds), as a crowd of froblins and
    // a human model mixed in (--model) has: a short quick stride and a long
    // slow one. Each agent's phase follows the ground it covers by its own
    // kind's stride, and each walks within its own clip's range of speeds.
    auto ground = flatTerrain(257, 1.0f);
    CrowdSettings settings = testSettings();
    settings.strideRadius = 0.4f;
    settings.kinds = {{0.6f, 1.1f, 2.5f}, {2.2f, 2.0f, 3.0f}};
    SpawnPattern spawn{Region::rect({20.0f, 20.0f}, {40.0f, 236.0f}), 30, 6, 0, 0.38f, 0.42f, 0.7f, 0.8f};
    auto crowd = makeCrowd(*ground, settings, {{"east", Region::rect({230.0f, 0.0f}, {256.0f, 256.0f})}}, {spawn});
    ASSERT_TRUE(crowd);
    constexpr int kSteps = 150;
    const CyclesWalked walked = walkCycles(*crowd, kSteps);
    const CrowdAgents& a = crowd->agents();
    for (size_t i = 0; i < a.size(); ++i) {
        const uint32_t id = a.id[i];
        const WalkerKind& kind = settings.kinds[id % 2];
        EXPECT_EQ(settings.kindOf(id).walkStrideLength, kind.walkStrideLength);
        const float stride = kind.walkStrideLength * a.radius[i] / settings.strideRadius;
        const float distance = glm::distance(walked.from[id], xz(a.position[i]));
        EXPECT_NEAR(float(walked.cycles[id]) * stride, distance, 0.02f * distance)
            << "agent " << id << " of kind " << id % 2;
        // Within its clip's pace: at least minWalkRate of it (the long
        // stride's natural 1.1 m/s makes 0.7 to 0.8 m/s a slow walk of it).
        const float natural = stride / kind.walkCycleSeconds;
        const float speed = distance / (float(kSteps) * settings.timeStep);
        EXPECT_GE(speed, settings.minWalkRate * natural * 0.98f) << "agent " << id;
        EXPECT_LE(speed, settings.maxWalkRate * natural * 1.02f) << "agent " << id;
    }
}

TEST(CrowdAnimation, StandingAgentsIdleAndArrivalsStop) {
    auto ground = flatTerrain(129, 1.0f);
    CrowdSettings settings = testSettings();
    // The goal covers the spawn: everybody has arrived at once and stays.
    auto crowd = makeCrowd(*ground, settings, {{"here", Region::disc({64.0f, 64.0f}, 30.0f), ArrivalPolicy::Stay}},
                           {{Region::disc({64.0f, 64.0f}, 10.0f), 20, 1}});
    ASSERT_TRUE(crowd);
    for (int s = 0; s < int(30.0f / settings.timeStep); ++s) crowd->step();
    const CrowdAgents& a = crowd->agents();
    EXPECT_EQ(crowd->stats().staying, a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a.clip[i], AgentClip::Idle) << "agent " << i;
        EXPECT_EQ(a.velocity[i], glm::vec2(0.0f)) << "an idle agent stands still: its feet would slide";
    }
}

} // namespace
} // namespace tessera::crowd::test
