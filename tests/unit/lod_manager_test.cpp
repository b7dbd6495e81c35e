// The LOD manager's CPU reference: tiers from the size on screen, hysteresis,
// cross-fades and the frame budget (docs/CROWD.md, "Rendering").
#include "tessera/core/Random.h"
#include "tessera/lod/LodManager.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>

using namespace tessera;
using lod::LodCharacter;
using lod::LodInstance;
using lod::LodManager;
using lod::LodPolicy;

namespace {

constexpr float kRadius = 0.8f; // a goblin's bounding sphere
constexpr uint32_t kHeight = 720;

/// Camera at the origin looking down -Z, 60 degrees, 16:9.
scene::Camera camera() {
    scene::Camera c;
    c.setPosition({0, 0, 0});
    return c;
}

lod::LodView view(const scene::Camera& c = camera(), float maxLevel = 64.0f) {
    return lod::LodView::fromCamera(c, kHeight, maxLevel);
}

float pixelsPerRadian() { return float(kHeight) / (2.0f * std::tan(0.5f * scene::Camera::kDefaultVerticalFov)); }

/// The distance at which the sphere covers `pixels`.
float distanceFor(float pixels) { return 2.0f * kRadius * pixelsPerRadian() / pixels; }

LodInstance at(float distance, uint32_t id, float x = 0.0f) {
    return {glm::vec4(x, 0.0f, -distance, kRadius), id, 0};
}

std::vector<LodCharacter> creature() {
    // 5,000 cage triangles, a 3 cm mean edge, a 300-triangle far mesh.
    return {{LodCharacter::levelPerPixelFor(0.03f, kRadius, 1.0f), 5000, 5000, 300}};
}

uint32_t tierOf(const lod::LodFrame& frame, uint32_t instance) {
    for (uint32_t t = 0; t < lod::kTierCount; ++t)
        for (const lod::LodDraw& d : frame.tiers[t])
            if (d.instance == instance && !d.fadingOut) return t;
    return TS_LOD_NONE;
}

/// The policy these tests were written for (the thresholds and edge of
/// their expected tiers and levels), whatever the shipped defaults are.
LodPolicy testPolicy() {
    LodPolicy policy;
    policy.nearPixels = 128.0f;
    policy.farPixels = 40.0f;
    policy.impostorPixels = 0.0f; // impostors only past the far budget, unless a test asks
    policy.targetEdgePixels = 1.0f;
    return policy;
}

LodPolicy noFade() {
    LodPolicy policy = testPolicy();
    policy.fadeFrames = 0;
    return policy;
}

} // namespace

TEST(LodManager, TiersFollowTheSizeOnScreen) {
    LodManager lods(noFade(), 1);
    const auto characters = creature();
    const std::vector<LodInstance> instances = {
        at(distanceFor(300.0f), 0), at(distanceFor(129.0f), 1), at(distanceFor(127.0f), 2),
        at(distanceFor(41.0f), 3),  at(distanceFor(39.0f), 4),  at(-5.0f, 5) /* behind the camera */,
        at(20.0f, 6, 200.0f) /* far to the side */};
    const lod::LodFrame& f = lods.update(instances, characters, view());
    EXPECT_EQ(tierOf(f, 0), TS_LOD_NEAR);
    EXPECT_EQ(tierOf(f, 1), TS_LOD_NEAR);
    EXPECT_EQ(tierOf(f, 2), TS_LOD_MIDDLE);
    EXPECT_EQ(tierOf(f, 3), TS_LOD_MIDDLE);
    EXPECT_EQ(tierOf(f, 4), TS_LOD_FAR);
    EXPECT_EQ(tierOf(f, 5), TS_LOD_NONE);
    EXPECT_EQ(tierOf(f, 6), TS_LOD_NONE);
    EXPECT_EQ(f.inView, 5u);
    // The near level follows the size: 300 px at 3 cm per 1.6 m.
    EXPECT_NEAR(f.tiers[TS_LOD_NEAR][0].level, 300.0f * 0.03f / 1.6f, 1e-3f);
    EXPECT_EQ(f.counts[TS_LOD_MIDDLE].triangles, 2u * 5000u);
    EXPECT_EQ(f.counts[TS_LOD_FAR].triangles, 300u);
}

TEST(LodManager, HysteresisKeepsAnOscillatingInstanceInOneTier) {
    // An agent walking back and forth across the near threshold, 5% either
    // side (the hysteresis is 15%): once it has crossed, it stays.
    LodManager lods(noFade(), 1);
    const auto characters = creature();
    uint32_t changes = 0, last = TS_LOD_NONE;
    for (int frame = 0; frame < 600; ++frame) {
        const float pixels = testPolicy().nearPixels * (1.0f + 0.05f * std::sin(float(frame) * 0.1f));
        const LodInstance instance = at(distanceFor(pixels), 7);
        const uint32_t tier = tierOf(lods.update({&instance, 1}, characters, view()), 0);
        if (last != TS_LOD_NONE && tier != last) ++changes;
        last = tier;
    }
    EXPECT_LE(changes, 1u);
    // Without hysteresis the same walk flips every half period.
    LodPolicy bare = noFade();
    bare.hysteresis = 0.0f;
    LodManager flicker(bare, 1);
    uint32_t flips = 0;
    last = TS_LOD_NONE;
    for (int frame = 0; frame < 600; ++frame) {
        const float pixels = testPolicy().nearPixels * (1.0f + 0.05f * std::sin(float(frame) * 0.1f));
        const LodInstance instance = at(distanceFor(pixels), 7);
        const uint32_t tier = tierOf(flicker.update({&instance, 1}, characters, view()), 0);
        if (last != TS_LOD_NONE && tier != last) ++flips;
        last = tier;
    }
    EXPECT_GT(flips, 10u);
}

TEST(LodManager, ATierChangeCrossFadesOverTheFadeFrames) {
    LodPolicy policy = testPolicy();
    policy.fadeFrames = 8;
    LodManager lods(policy, 1);
    const auto characters = creature();
    LodInstance instance = at(distanceFor(60.0f), 3);
    lods.update({&instance, 1}, characters, view());
    ASSERT_EQ(tierOf(lods.frame(), 0), TS_LOD_MIDDLE);
    instance = at(distanceFor(30.0f), 3); // now far
    float previousCoverage = 0.0f;
    for (uint32_t frame = 0; frame < policy.fadeFrames; ++frame) {
        const lod::LodFrame& f = lods.update({&instance, 1}, characters, view());
        ASSERT_EQ(f.tiers[TS_LOD_FAR].size(), 1u);
        ASSERT_EQ(f.tiers[TS_LOD_MIDDLE].size(), 1u) << "frame " << frame;
        const lod::LodDraw in = f.tiers[TS_LOD_FAR][0], out = f.tiers[TS_LOD_MIDDLE][0];
        EXPECT_FALSE(in.fadingOut);
        EXPECT_TRUE(out.fadingOut);
        EXPECT_FLOAT_EQ(in.coverage + out.coverage, 1.0f);
        EXPECT_GT(in.coverage, previousCoverage);
        previousCoverage = in.coverage;
        EXPECT_EQ(f.counts[TS_LOD_MIDDLE].fading, 1u);
    }
    const lod::LodFrame& done = lods.update({&instance, 1}, characters, view());
    EXPECT_TRUE(done.tiers[TS_LOD_MIDDLE].empty());
    ASSERT_EQ(done.tiers[TS_LOD_FAR].size(), 1u);
    EXPECT_EQ(done.tiers[TS_LOD_FAR][0].coverage, 1.0f);
}

TEST(LodManager, ComingIntoViewDoesNotFade) {
    LodManager lods(testPolicy(), 1);
    const auto characters = creature();
    LodInstance instance = at(-10.0f, 1);
    lods.update({&instance, 1}, characters, view());
    EXPECT_EQ(lods.frame().inView, 0u);
    instance = at(10.0f, 1);
    const lod::LodFrame& f = lods.update({&instance, 1}, characters, view());
    EXPECT_EQ(f.counts[TS_LOD_MIDDLE].instances, 1u);
    EXPECT_EQ(f.counts[TS_LOD_MIDDLE].fading, 0u);
}

TEST(LodManager, TheBudgetCapsNearInstancesAndTessellatedTriangles) {
    LodPolicy policy = testPolicy();
    policy.budget.maxNearInstances = 3;
    policy.budget.maxTessellatedTriangles = 2'000'000;
    LodManager lods(policy, 1);
    const auto characters = creature();
    std::vector<LodInstance> instances;
    for (uint32_t i = 0; i < 40; ++i) instances.push_back(at(2.0f + 0.1f * float(i), i, 0.3f * float(i % 5) - 0.6f));
    const lod::LodFrame& f = lods.update(instances, characters, view());
    EXPECT_EQ(f.counts[TS_LOD_NEAR].instances, 3u);
    EXPECT_LE(f.counts[TS_LOD_NEAR].triangles, policy.budget.maxTessellatedTriangles);
    // The nearest (largest on screen) are the ones tessellated.
    for (const lod::LodDraw& d : f.tiers[TS_LOD_NEAR]) EXPECT_LT(d.instance, 3u);
    EXPECT_EQ(f.budgetDemoted, 37u);
    EXPECT_EQ(f.counts[TS_LOD_MIDDLE].instances, 37u);
}

TEST(LodManager, OneHugeInstanceGetsALowerLevelCapNotAnOverrun) {
    // A model filling the screen: its size asks for level 64 (5,000 cage
    // triangles become tens of millions); a tiny budget lowers the cap.
    LodPolicy policy = noFade();
    policy.budget.maxTessellatedTriangles = 100'000;
    LodManager lods(policy, 1);
    const auto characters = creature();
    const LodInstance instance = at(1.0f, 0);
    const lod::LodFrame& f = lods.update({&instance, 1}, characters, view());
    ASSERT_EQ(f.counts[TS_LOD_NEAR].instances, 1u);
    EXPECT_LE(f.counts[TS_LOD_NEAR].triangles, 100'000u);
    EXPECT_GE(f.counts[TS_LOD_NEAR].triangles, 5000u);
    EXPECT_LT(f.params.levels.x, 64.0f);
    // A budget below the bare cage draws it untessellated (middle tier).
    policy.budget.maxTessellatedTriangles = 4000;
    LodManager bare(policy, 1);
    const lod::LodFrame& g = bare.update({&instance, 1}, characters, view());
    EXPECT_EQ(g.counts[TS_LOD_NEAR].instances, 0u);
    EXPECT_EQ(g.counts[TS_LOD_MIDDLE].instances, 1u);
}

TEST(LodManager, PastTheFarCapTheSmallestAreImpostorsNeverDropped) {
    LodPolicy policy = noFade();
    policy.budget.maxFarInstances = 10;
    LodManager lods(policy, 1);
    const auto characters = creature();
    std::vector<LodInstance> instances; // 5 middle (40 px and more), 25 far
    for (uint32_t i = 0; i < 30; ++i) instances.push_back(at(distanceFor(61.0f - 2.0f * float(i)), i));
    const lod::LodFrame& f = lods.update(instances, characters, view());
    EXPECT_EQ(f.counts[TS_LOD_MIDDLE].instances, 11u);
    EXPECT_EQ(f.counts[TS_LOD_FAR].instances, 10u);
    EXPECT_EQ(f.counts[TS_LOD_IMPOSTOR].instances, 9u);
    EXPECT_EQ(f.counts[TS_LOD_IMPOSTOR].triangles, 18u) << "a card is two triangles";
    EXPECT_EQ(f.pastFarBudget, 9u);
    EXPECT_EQ(f.inView, 30u);
    for (const lod::LodDraw& d : f.tiers[TS_LOD_FAR]) EXPECT_LT(d.instance, 21u);
    for (const lod::LodDraw& d : f.tiers[TS_LOD_IMPOSTOR]) EXPECT_GE(d.instance, 21u);
}

TEST(LodManager, BelowTheImpostorThresholdACreatureIsACardWithHysteresis) {
    LodPolicy policy = noFade();
    policy.impostorPixels = 16.0f;
    LodManager lods(policy, 1);
    const auto characters = creature();
    std::vector<LodInstance> instances = {at(distanceFor(17.0f), 0), at(distanceFor(15.0f), 1),
                                          at(distanceFor(200.0f), 2)};
    const lod::LodFrame& f = lods.update(instances, characters, view());
    EXPECT_EQ(tierOf(f, 0), TS_LOD_FAR);
    EXPECT_EQ(tierOf(f, 1), TS_LOD_IMPOSTOR);
    EXPECT_EQ(f.pastFarBudget, 0u) << "by its size, not the budget";
    // Shrunk within the hysteresis (15% below 16 px), the far one stays; the
    // card needs the threshold itself to come back to the far mesh.
    instances[0] = at(distanceFor(14.0f), 0);
    instances[1] = at(distanceFor(15.9f), 1);
    lods.update(instances, characters, view());
    EXPECT_EQ(tierOf(lods.frame(), 0), TS_LOD_FAR);
    EXPECT_EQ(tierOf(lods.frame(), 1), TS_LOD_IMPOSTOR);
    instances[0] = at(distanceFor(13.0f), 0);
    instances[1] = at(distanceFor(16.5f), 1);
    lods.update(instances, characters, view());
    EXPECT_EQ(tierOf(lods.frame(), 0), TS_LOD_IMPOSTOR);
    EXPECT_EQ(tierOf(lods.frame(), 1), TS_LOD_FAR);
}

TEST(LodManager, EveryCreatureInViewIsDrawnWhateverTheBudgets) {
    // Budgets choose the representation, never whether (issue 31, item 0):
    // with every mesh tier's budget at zero the crowd is all cards.
    LodPolicy policy = testPolicy();
    policy.budget.maxNearInstances = 0;
    policy.budget.maxMiddleInstances = 0;
    policy.budget.maxFarInstances = 0;
    LodManager lods(policy, 1);
    const auto characters = creature();
    std::vector<LodInstance> instances;
    for (uint32_t i = 0; i < 40; ++i) instances.push_back(at(distanceFor(20.0f + 10.0f * float(i)), i));
    for (int frame = 0; frame < 3; ++frame) {
        const lod::LodFrame& f = lods.update(instances, characters, view());
        uint32_t drawn = 0;
        for (uint32_t t = 0; t < lod::kTierCount; ++t)
            for (const lod::LodDraw& d : f.tiers[t]) drawn += !d.fadingOut;
        EXPECT_EQ(drawn, f.inView);
        EXPECT_EQ(f.inView, 40u);
    }
}

TEST(LodManager, ASpentBudgetNeverHandsAMeshMadeForFewerPixels) {
    // The near budget's demotions take the middle tier (the cage holds at
    // any size); the middle budget's take the far mesh only below the far
    // threshold, its size: creatures above it stay in the middle tier,
    // over the budget (docs/CROWD.md 6.2, "Fallbacks").
    LodPolicy policy = noFade();
    policy.budget.maxNearInstances = 1;
    policy.budget.maxMiddleInstances = 6;
    LodManager lods(policy, 1);
    const auto characters = creature();
    std::vector<LodInstance> instances;
    for (uint32_t i = 0; i < 4; ++i) instances.push_back(at(distanceFor(200.0f + 10.0f * float(i)), i)); // near
    for (uint32_t i = 4; i < 12; ++i) instances.push_back(at(distanceFor(45.0f + 5.0f * float(i)), i));  // middle
    lods.update(instances, characters, view());
    EXPECT_EQ(lods.frame().counts[TS_LOD_NEAR].instances, 1u);
    EXPECT_EQ(tierOf(lods.frame(), 3), TS_LOD_NEAR) << "the largest is tessellated";
    EXPECT_EQ(lods.frame().counts[TS_LOD_MIDDLE].instances, 11u) << "every other one above the far threshold";
    EXPECT_EQ(lods.frame().counts[TS_LOD_FAR].instances, 0u);
    // Shrunk into the hysteresis band (34 to 40 px), those kept in the
    // middle tier by it are the budget's to demote: the smallest go, the
    // three demoted from near taking half the budget.
    for (uint32_t i = 4; i < 12; ++i) instances[i] = at(distanceFor(34.5f + 0.5f * float(i - 4)), i);
    const lod::LodFrame& f = lods.update(instances, characters, view());
    EXPECT_EQ(f.counts[TS_LOD_MIDDLE].instances, 3u + 3u) << "three demoted from near, the three largest shrunk";
    EXPECT_EQ(f.counts[TS_LOD_FAR].instances, 5u);
    for (uint32_t i = 9; i < 12; ++i) EXPECT_EQ(tierOf(f, i), TS_LOD_MIDDLE) << i;
}

TEST(LodManager, AMovingCameraNeverExceedsTheBudgetAndEveryPathAgrees) {
    // A crowd of 6,000 on a plane and a camera flying through it: every
    // frame stays within every budget, cross-fades included, and the per-tier
    // lists are what the shared per-instance rule gives from the frame's
    // parameters (what the GPU passes run).
    LodPolicy policy = LodPolicy::forDevice(lod::DeviceClass::Cpu);
    policy.budget.maxFarInstances = 100; // spent in most frames: the rest become impostors
    LodManager lods(policy, 2);
    const auto characters = creature();
    Random random(11);
    std::vector<LodInstance> instances;
    for (uint32_t i = 0; i < 6000; ++i)
        instances.push_back({glm::vec4(random.range(-60.0f, 60.0f), 0.0f, random.range(-60.0f, 60.0f), kRadius),
                             i * 7 + 3, 0});
    std::vector<uint32_t> gpuState(6000 * 7 + 3, shader::tsLodStateNone());
    uint32_t demoted = 0, fading = 0, nearFrames = 0, pastFar = 0;
    for (int frame = 0; frame < 240; ++frame) {
        scene::Camera c;
        const float progress = float(frame) / 240.0f;
        c.setPosition({-50.0f + 100.0f * progress, 1.7f, 20.0f * std::sin(6.0f * progress)});
        c.setYaw(-1.2f + 2.4f * progress);
        const lod::LodFrame& f = lods.update(instances, characters, view(c));
        EXPECT_LE(f.counts[TS_LOD_NEAR].instances, policy.budget.maxNearInstances);
        EXPECT_LE(f.counts[TS_LOD_NEAR].triangles, policy.budget.maxTessellatedTriangles);
        EXPECT_LE(f.counts[TS_LOD_FAR].instances, policy.budget.maxFarInstances);
        // The middle budget may be exceeded, but only by creatures the far
        // mesh is not made for (at least the far threshold).
        uint32_t aboveFar = 0;
        for (const lod::LodDraw& d : f.tiers[TS_LOD_MIDDLE])
            aboveFar += !d.fadingOut && shader::tsLodPixels(instances[d.instance].sphere, f.params) >= policy.farPixels;
        EXPECT_LE(f.counts[TS_LOD_MIDDLE].instances, std::max(policy.budget.maxMiddleInstances, aboveFar + f.counts[TS_LOD_MIDDLE].fading));
        for (const lod::LodDraw& d : f.tiers[TS_LOD_FAR])
            if (!d.fadingOut) {
                EXPECT_LT(shader::tsLodPixels(instances[d.instance].sphere, f.params), policy.farPixels);
            }
        demoted += f.budgetDemoted;
        pastFar += f.pastFarBudget;
        // Every instance in view is drawn, in one tier or another (a fading
        // instance twice: its two copies both count as fading).
        uint32_t total = 0, fadingCopies = 0;
        for (const lod::LodTierCount& count : f.counts) {
            total += count.instances;
            fadingCopies += count.fading;
        }
        EXPECT_EQ(total, f.inView + fadingCopies / 2) << "frame " << frame;
        nearFrames += f.counts[TS_LOD_NEAR].instances > 0;
        for (const lod::LodTierCount& count : f.counts) fading += count.fading;
        std::array<uint32_t, lod::kTierCount> drawn{};
        for (const LodInstance& instance : instances) {
            uint32_t& s = gpuState[instance.id];
            s = shader::tsLodUpdate(s, instance.sphere, f.params, nullptr);
            const uint32_t tier = shader::tsLodStateTier(s);
            if (tier == TS_LOD_NONE) continue;
            ++drawn[tier];
            if (shader::tsLodStateFade(s) > 0u) ++drawn[shader::tsLodStatePrevious(s)];
            ASSERT_EQ(s, lods.state(instance.id));
        }
        for (uint32_t t = 0; t < lod::kTierCount; ++t) EXPECT_EQ(drawn[t], f.counts[t].instances);
    }
    // The flight does exercise the budget and the fades.
    EXPECT_GT(demoted, 0u);
    EXPECT_GT(pastFar, 0u);
    EXPECT_GT(fading, 0u);
    EXPECT_GT(nearFrames, 10u);
    std::printf("flight: %u demotions, %u impostors past the far budget, %u fading copies, %u frames with near "
                "instances\n",
                demoted, pastFar, fading, nearFrames);
}

TEST(LodManager, SameAnswerOnAnyThreadCount) {
    const auto characters = creature();
    Random random(5);
    std::vector<LodInstance> instances;
    for (uint32_t i = 0; i < 20000; ++i)
        instances.push_back({glm::vec4(random.range(-100.0f, 100.0f), 0.0f, random.range(-200.0f, 0.0f), kRadius),
                             i, 0});
    LodManager one(testPolicy(), 1), four(testPolicy(), 4);
    const lod::LodFrame& a = one.update(instances, characters, view());
    const lod::LodFrame& b = four.update(instances, characters, view());
    for (uint32_t t = 0; t < lod::kTierCount; ++t) {
        ASSERT_EQ(a.tiers[t].size(), b.tiers[t].size());
        for (size_t k = 0; k < a.tiers[t].size(); ++k) EXPECT_EQ(a.tiers[t][k].instance, b.tiers[t][k].instance);
    }
}

// A flight over a crowd behind a ridge (fades, budget demotions, impostors,
// horizon culling): 6,000 instances over 120 x 120 m, ids shuffled.
std::vector<LodInstance> ridgeCrowd() {
    Random random(17);
    std::vector<LodInstance> instances;
    for (uint32_t i = 0; i < 6000; ++i)
        instances.push_back({glm::vec4(random.range(-60.0f, 60.0f), 0.0f, random.range(-60.0f, 60.0f), kRadius),
                             (i * 37) % 6000, 0});
    return instances;
}

// The flight's view at `frame` of 120, over 16 x 16 cells of 8 m from
// (-64, -64) with a ridge 3 m high along z = 0.
lod::LodView ridgeView(int frame) {
    scene::Camera c;
    const float progress = float(frame) / 120.0f;
    c.setPosition({-50.0f + 100.0f * progress, 1.7f, 30.0f - 40.0f * progress});
    c.setYaw(-1.2f + 2.4f * progress);
    static const std::vector<float> lowest = [] {
        std::vector<float> cells(16 * 16, -1.0f);
        for (uint32_t x = 0; x < 16; ++x) cells[8 * 16 + x] = 3.0f;
        return cells;
    }();
    lod::LodView v = view(c);
    v.occluders = lowest;
    v.occluderGrid = glm::vec4(-64.0f, -64.0f, 8.0f, 16.0f);
    return v;
}

TEST(LodManager, WithoutListsEveryCountCutAndStateIsTheSame) {
    // The runtime runs the manager without its per-tier lists; a camera
    // flying over a crowd behind a ridge (fades, budget demotions, impostors,
    // horizon culling) gives the same parameters, counts and state words.
    LodPolicy policy = LodPolicy::forDevice(lod::DeviceClass::Cpu);
    policy.budget.maxFarInstances = 100;
    LodManager with(policy, 2), without(policy, 2);
    without.keepLists(false);
    const auto characters = creature();
    const std::vector<LodInstance> instances = ridgeCrowd();
    uint32_t hidden = 0, impostors = 0;
    for (int frame = 0; frame < 120; ++frame) {
        const lod::LodView v = ridgeView(frame);
        const lod::LodFrame& a = with.update(instances, characters, v);
        const lod::LodFrame& b = without.update(instances, characters, v);
        ASSERT_EQ(std::memcmp(&a.params, &b.params, sizeof a.params), 0) << "frame " << frame;
        for (uint32_t t = 0; t < lod::kTierCount; ++t) {
            EXPECT_EQ(a.counts[t].instances, b.counts[t].instances);
            EXPECT_EQ(a.counts[t].fading, b.counts[t].fading);
            EXPECT_EQ(a.counts[t].triangles, b.counts[t].triangles);
            EXPECT_EQ(a.hidden[t], b.hidden[t]);
            EXPECT_EQ(a.tiers[t].size(), a.counts[t].instances);
            EXPECT_TRUE(b.tiers[t].empty());
            hidden += a.hidden[t];
        }
        EXPECT_EQ(a.inView, b.inView);
        EXPECT_EQ(a.pastFarBudget, b.pastFarBudget);
        EXPECT_EQ(a.budgetDemoted, b.budgetDemoted);
        EXPECT_EQ(a.tierChanges, b.tierChanges);
        impostors += a.counts[TS_LOD_IMPOSTOR].instances;
        for (const LodInstance& instance : instances) ASSERT_EQ(with.state(instance.id), without.state(instance.id));
    }
    EXPECT_GT(hidden, 0u) << "the ridge hides part of the crowd";
    EXPECT_GT(impostors, 0u);
}

TEST(LodManager, UntestedImpostorsChangeNoParameterNorAnyMeshTier) {
    // The runtime tests only the instances a budget counts against the
    // horizon (the backends cull the impostors themselves): the same flight
    // over a crowd behind a ridge gives the reference's parameters (all the
    // GPU reads), mesh tiers' counts and hidden counts every frame; the
    // impostors the ridge hides count as impostors in view, and countHidden
    // still finds every hidden instance.
    LodPolicy policy = LodPolicy::forDevice(lod::DeviceClass::Cpu);
    policy.budget.maxFarInstances = 100;
    LodManager reference(policy, 2), runtime(policy, 2);
    runtime.keepLists(false);
    runtime.testEveryHorizon(false);
    const auto characters = creature();
    const std::vector<LodInstance> instances = ridgeCrowd();
    uint32_t untested = 0, hiddenImpostors = 0, hiddenMeshes = 0;
    for (int frame = 0; frame < 120; ++frame) {
        const lod::LodView v = ridgeView(frame);
        const lod::LodFrame& a = reference.update(instances, characters, v);
        const lod::LodFrame& b = runtime.update(instances, characters, v);
        ASSERT_EQ(std::memcmp(&a.params, &b.params, sizeof a.params), 0) << "frame " << frame;
        // (Not their fading counts: an instance coming out from behind the
        // ridge into a mesh tier pops in for the reference, and fades in
        // from the impostor the runtime took it for; on the GPU, whose own
        // states are the reference's, it pops in.)
        for (uint32_t t = TS_LOD_NEAR; t <= TS_LOD_FAR; ++t) {
            EXPECT_EQ(a.counts[t].instances, b.counts[t].instances) << "frame " << frame << " tier " << t;
            EXPECT_EQ(a.counts[t].triangles, b.counts[t].triangles);
            EXPECT_EQ(a.hidden[t], b.hidden[t]);
            hiddenMeshes += a.hidden[t];
        }
        EXPECT_EQ(a.pastFarBudget, b.pastFarBudget);
        EXPECT_EQ(a.budgetDemoted, b.budgetDemoted);
        EXPECT_EQ(a.untested, 0u);
        EXPECT_EQ(b.inView, a.inView + a.hidden[TS_LOD_IMPOSTOR] - b.hidden[TS_LOD_IMPOSTOR]);
        untested += b.untested;
        hiddenImpostors += a.hidden[TS_LOD_IMPOSTOR] - b.hidden[TS_LOD_IMPOSTOR];
        // The same instances hidden, whichever manager counts them.
        uint32_t hiddenA = 0, hiddenB = 0;
        for (uint32_t t = 0; t < lod::kTierCount; ++t) hiddenA += a.hidden[t];
        for (uint32_t h : runtime.countHidden(instances)) hiddenB += h;
        EXPECT_EQ(hiddenA, hiddenB) << "frame " << frame;
        // Wherever either holds a mesh tier, both hold the same one.
        for (const LodInstance& instance : instances) {
            const uint32_t ta = shader::tsLodStateTier(reference.state(instance.id));
            const uint32_t tb = shader::tsLodStateTier(runtime.state(instance.id));
            if (ta <= TS_LOD_FAR || tb <= TS_LOD_FAR) {
                ASSERT_EQ(ta, tb) << "frame " << frame;
            }
        }
    }
    EXPECT_GT(untested, 0u);
    EXPECT_GT(hiddenImpostors, 0u) << "impostors the ridge hides, which the runtime leaves to the backends";
    EXPECT_GT(hiddenMeshes, 0u) << "mesh candidates the ridge hides, which both cull";
}

TEST(LodManager, InstancesInAnyOrderKeepTheirStatesById) {
    // The manager keeps states in instance order while the ids stay in place
    // and moves them by id when they do: a crowd re-sorted now and then, with
    // agents leaving and coming back, gets the states and counts of the same
    // crowd given in one fixed order.
    const auto characters = creature();
    Random random(29);
    std::vector<LodInstance> fixed;
    for (uint32_t i = 0; i < 3000; ++i)
        fixed.push_back({glm::vec4(random.range(-40.0f, 40.0f), 0.0f, random.range(-80.0f, 0.0f), kRadius), i * 3 + 1,
                         0});
    LodPolicy policy = testPolicy();
    policy.budget.maxFarInstances = 200;
    LodManager inOrder(policy, 2), shuffled(policy, 2);
    std::vector<uint32_t> order(fixed.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    // The shared per-instance rule by id, as a backend's state buffer runs it.
    std::vector<uint32_t> rule(fixed.size() * 3 + 1, shader::tsLodStateNone());
    for (int frame = 0; frame < 90; ++frame) {
        for (LodInstance& instance : fixed) instance.sphere.z += 0.4f * std::sin(0.1f * float(frame + instance.id));
        // Every 16 frames a new order; between frames 30 and 40 a tenth of the
        // crowd is away (both managers see the same set).
        if (frame % 16 == 0)
            for (uint32_t i = uint32_t(order.size()) - 1; i > 0; --i) std::swap(order[i], order[random.below(i + 1)]);
        const bool away = frame >= 30 && frame < 40;
        std::vector<LodInstance> present, permuted;
        for (const LodInstance& instance : fixed)
            if (!away || instance.id % 10 != 0) present.push_back(instance);
        for (uint32_t k : order)
            if (!away || fixed[k].id % 10 != 0) permuted.push_back(fixed[k]);
        const scene::Camera c = camera();
        const lod::LodFrame& a = inOrder.update(present, characters, view(c));
        const lod::LodFrame& b = shuffled.update(permuted, characters, view(c));
        ASSERT_EQ(std::memcmp(&a.params, &b.params, sizeof a.params), 0) << "frame " << frame;
        for (uint32_t t = 0; t < lod::kTierCount; ++t) EXPECT_EQ(a.counts[t].instances, b.counts[t].instances);
        EXPECT_EQ(a.tierChanges, b.tierChanges);
        for (const LodInstance& instance : permuted)
            rule[instance.id] = shader::tsLodUpdate(rule[instance.id], instance.sphere, b.params, nullptr);
        for (const LodInstance& instance : fixed) {
            ASSERT_EQ(inOrder.state(instance.id), shuffled.state(instance.id)) << "frame " << frame << " id " << instance.id;
            ASSERT_EQ(shuffled.state(instance.id), rule[instance.id]) << "frame " << frame << " id " << instance.id;
        }
    }
}

TEST(LodPolicy, BadSettingsAreRefusedWithAMessage) {
    LodPolicy policy = testPolicy();
    EXPECT_TRUE(policy.validate().ok());
    policy.budget.maxTessellatedTriangles = 0;
    ASSERT_FALSE(policy.validate().ok());
    EXPECT_NE(policy.validate().error().message.find("budget of zero"), std::string::npos);
    policy = {};
    policy.impostorPixels = policy.farPixels + 1.0f;
    ASSERT_FALSE(policy.validate().ok());
    EXPECT_NE(policy.validate().error().message.find("impostor threshold"), std::string::npos);
    policy = {};
    policy.farPixels = 500.0f;
    EXPECT_FALSE(policy.validate().ok());
    policy = {};
    policy.hysteresis = 1.5f;
    EXPECT_FALSE(policy.validate().ok());
    policy = {};
    policy.fadeFrames = 100;
    EXPECT_FALSE(policy.validate().ok());
    EXPECT_LT(LodPolicy::forDevice(lod::DeviceClass::Cpu).budget.maxTessellatedTriangles,
              LodPolicy::forDevice(lod::DeviceClass::Gpu).budget.maxTessellatedTriangles);
}
