// Baked animation for crowds: the baked rows against Pose::palette at every
// frame, the blend between frames against the exact pose (skinned cage
// positions, relative to the model's size), the looping wrap, the rest pose,
// combine's offsets and the memory figure.
#include "tessera/character/BakedAnimation.h"
#include "tessera/character/BakedVertices.h"
#include "tessera/shaders/CompressedVertex.h"
#include "tessera/character/Pose.h"
#include "tessera/character/SkinnedVertex.h"

#include "../content/GlbTestCharacter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <iostream>

using namespace tessera;
using namespace tessera::character;

namespace {

constexpr float kPi = 3.14159265358979f;

glm::vec4 quatValue(const glm::quat& q) {
    return {q.x, q.y, q.z, q.w};
}

// A walking leg: root -> hip -> knee -> foot, the hip swinging +-0.5 rad, the
// knee bending up to 0.8 rad and the root bobbing 3 cm, a 1.1 s loop keyed at
// 60 Hz (finer than the 30 Hz bake, so frames fall between keys as they do
// for any clip not keyed at the bake rate). The cage is a box-section column
// from the hip (y = 1) to the foot (y = 0) plus a toe 25 cm forward, the
// joints blended across the knee as skinning does.
CharacterAsset makeLeg() {
    CharacterAsset asset;
    asset.name = "leg";
    asset.skeleton.nodes = {{"root", -1, {}}, {"hip", 0, {}}, {"knee", 1, {}}, {"foot", 2, {}}};
    asset.skeleton.nodes[1].rest.translation = {0.0f, 1.0f, 0.0f};
    asset.skeleton.nodes[2].rest.translation = {0.0f, -0.5f, 0.0f};
    asset.skeleton.nodes[3].rest.translation = {0.0f, -0.5f, 0.0f};
    const float jointHeight[] = {1.0f, 0.5f, 0.0f};
    for (uint32_t j = 0; j < 3; ++j) {
        asset.cage.bindings.push_back({j + 1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -jointHeight[j], 0.0f))});
    }
    for (int level = 0; level <= 10; ++level) {
        const float y = 1.0f - 0.1f * float(level);
        // Hip only above 0.6, knee only below 0.4 (to the foot), a linear blend between.
        const float knee = std::clamp((0.6f - y) / 0.2f, 0.0f, 1.0f);
        for (glm::vec2 xz :
             {glm::vec2(-0.08f, -0.08f), glm::vec2(0.08f, -0.08f), glm::vec2(0.08f, 0.08f), glm::vec2(-0.08f, 0.08f)}) {
            CageVertex v;
            v.position = {xz.x, y, xz.y};
            v.joints = {0, 1, 0, 0};
            v.weights = {1.0f - knee, knee, 0.0f, 0.0f};
            asset.cage.vertices.push_back(v);
        }
    }
    CageVertex toe;
    toe.position = {0.0f, 0.0f, 0.25f};
    toe.joints = {2, 0, 0, 0};
    asset.cage.vertices.push_back(toe);

    AnimationClip walk;
    walk.name = "walk";
    AnimationChannel bob{0, AnimationPath::Translation, AnimationInterpolation::Linear, {}, {}};
    AnimationChannel hip{1, AnimationPath::Rotation, AnimationInterpolation::Linear, {}, {}};
    AnimationChannel knee{2, AnimationPath::Rotation, AnimationInterpolation::Linear, {}, {}};
    const float period = 1.1f;
    for (int k = 0; k <= 66; ++k) {
        const float t = float(k) / 60.0f;
        const float a = 2.0f * kPi * t / period;
        for (AnimationChannel* c : {&bob, &hip, &knee}) c->times.push_back(t);
        bob.values.emplace_back(0.0f, 0.03f * std::sin(2.0f * a), 0.0f, 0.0f);
        hip.values.push_back(quatValue(glm::angleAxis(0.5f * std::sin(a), glm::vec3(1.0f, 0.0f, 0.0f))));
        knee.values.push_back(quatValue(glm::angleAxis(-0.4f * (1.0f - std::cos(a)), glm::vec3(1.0f, 0.0f, 0.0f))));
    }
    walk.channels = {bob, hip, knee};
    asset.clips.push_back(walk);
    return asset;
}

float modelSize(const CharacterAsset& asset) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const CageVertex& v : asset.cage.vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    return glm::length(hi - lo);
}

float maxMatrixDifference(const glm::mat4& a, const glm::mat4& b) {
    float d = 0.0f;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
    }
    return d;
}

std::vector<glm::mat4> posePalette(const CharacterAsset& asset, const AnimationClip* clip, float seconds,
                                   bool loop = true) {
    Pose pose(asset.skeleton);
    pose.reset();
    if (clip) pose.apply(*clip, seconds, loop);
    pose.computeGlobals();
    std::vector<glm::mat4> palette;
    pose.palette(asset.cage, palette);
    return palette;
}

// The largest distance between the cage skinned with the exact pose at
// `phase` and with the baked blend, over `samples` phases spread over the
// cycle (none of them on a frame), relative to the model's size.
float maxRelativeCageError(const CharacterAsset& asset, const BakedAnimation& baked, uint32_t assetClip, int samples) {
    const AnimationClip& clip = asset.clips[assetClip];
    const uint32_t index = bakedClipIndex(assetClip);
    std::vector<glm::mat4> exact, blended;
    float worst = 0.0f;
    for (int s = 0; s < samples; ++s) {
        const float phase = (float(s) + 0.37f) / float(samples);
        exact = posePalette(asset, &clip, phase * clip.duration());
        evaluateBakedPalette(baked, index, phase, blended);
        for (const CageVertex& v : asset.cage.vertices) {
            const glm::vec3 a = skinVertex(v, exact).position;
            const glm::vec3 b = skinVertex(v, blended).position;
            worst = std::max(worst, glm::length(a - b));
        }
    }
    return worst / modelSize(asset);
}

} // namespace

TEST(BakedAnimation, FramePairSelection) {
    shader::BakedClip clip{};
    clip.frames = glm::uvec4(0u, 5u, 1u, 0u); // four intervals, clamped
    uint32_t f0 = 9, f1 = 9;
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, 0.0f, f0, f1), 0.0f);
    EXPECT_EQ(f0, 0u);
    EXPECT_EQ(f1, 1u);
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, 0.375f, f0, f1), 0.5f);
    EXPECT_EQ(f0, 1u);
    EXPECT_EQ(f1, 2u);
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, 1.0f, f0, f1), 1.0f); // the last frame, from the last pair
    EXPECT_EQ(f0, 3u);
    EXPECT_EQ(f1, 4u);
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, 7.0f, f0, f1), 1.0f);
    EXPECT_EQ(f0, 3u);
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, -3.0f, f0, f1), 0.0f);
    EXPECT_EQ(f0, 0u);

    clip.frames.w = 1u; // looping: whole cycles wrap away
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, 2.375f, f0, f1), 0.5f);
    EXPECT_EQ(f0, 1u);
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, -0.625f, f0, f1), 0.5f);
    EXPECT_EQ(f0, 1u);
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, 1.0f, f0, f1), 0.0f);
    EXPECT_EQ(f0, 0u);

    clip.frames.y = 1u; // a rest pose
    EXPECT_FLOAT_EQ(shader::tsBakedFramePair(clip, 0.7f, f0, f1), 0.0f);
    EXPECT_EQ(f0, 0u);
    EXPECT_EQ(f1, 0u);
}

TEST(BakedAnimation, FrameCountsTimingAndBytes) {
    const CharacterAsset tube = test::makeTestCharacter();
    const BakedAnimation baked = bakeAnimation(tube);
    // Rest pose, bend (1 s), blink (0.25 s), nod (2 s) at 30 per second:
    // 1, 31, ceil(7.5) + 1 = 9 and 61 frames of 3 joints.
    ASSERT_EQ(baked.clips.size(), 4u);
    EXPECT_EQ(baked.characterClipBase, std::vector<uint32_t>{0u});
    const uint32_t frames[] = {1u, 31u, 9u, 61u};
    uint32_t first = 0;
    for (size_t c = 0; c < 4; ++c) {
        EXPECT_EQ(baked.clips[c].frames.x, first) << c;
        EXPECT_EQ(baked.clips[c].frames.y, frames[c]) << c;
        EXPECT_EQ(baked.clips[c].frames.z, 3u) << c;
        EXPECT_EQ(baked.clips[c].frames.w, 1u) << c;
        first += frames[c] * 3u * TS_BAKED_JOINT_TEXELS;
    }
    EXPECT_EQ(baked.texelCount(), size_t(first));
    EXPECT_EQ(baked.texelCount(), 918u);
    EXPECT_EQ(baked.bytes(), 918u * 16u + 4u * 32u);
    EXPECT_EQ(baked.clips[0].timing, glm::vec4(0.0f));
    EXPECT_FLOAT_EQ(baked.clips[2].timing.x, 0.25f);
    EXPECT_FLOAT_EQ(baked.clips[2].timing.y, 4.0f);
    EXPECT_FLOAT_EQ(baked.clips[2].timing.z, 32.0f); // 8 intervals over 0.25 s
    EXPECT_FLOAT_EQ(bakedPhase(baked.clips[3], 0.5f), 0.25f);

    // 1.1 s at 30 per second is 33 intervals in float too, not 34.
    const CharacterAsset leg = makeLeg();
    EXPECT_EQ(bakeAnimation(leg).clips[1].frames.y, 34u);
    EXPECT_EQ(bakeAnimation(leg, {60.0f, true}).clips[1].frames.y, 67u);
    EXPECT_EQ(bakeAnimation(leg, {0.1f, true}).clips[1].frames.y, 2u); // never fewer than 2
}

TEST(BakedAnimation, RowsArePosePaletteAtEveryFrame) {
    for (const CharacterAsset& asset : {test::makeTestCharacter(), makeLeg()}) {
        for (bool loop : {true, false}) {
            const BakedAnimation baked = bakeAnimation(asset, {30.0f, loop});
            for (size_t i = 0; i < asset.clips.size(); ++i) {
                const AnimationClip& clip = asset.clips[i];
                const shader::BakedClip& record = baked.clips[bakedClipIndex(uint32_t(i))];
                const uint32_t frames = record.frames.y;
                for (uint32_t f = 0; f < frames; ++f) {
                    // The looping copy of frame 0 is checked in LoopingWrapIsContinuous.
                    const uint32_t source = loop && f + 1 == frames ? 0u : f;
                    const float t = float(double(clip.duration()) * source / (frames - 1));
                    const std::vector<glm::mat4> palette = posePalette(asset, &clip, t, false);
                    for (uint32_t j = 0; j < record.frames.z; ++j) {
                        const size_t texel = shader::tsBakedJointTexel(record, f, j);
                        for (int r = 0; r < 3; ++r) {
                            const glm::vec4 row = baked.rows[texel + size_t(r)];
                            const glm::mat4& m = palette[j];
                            // Exact: the rows are the palette's own floats.
                            EXPECT_EQ(row, glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]))
                                << asset.name << " clip " << i << " frame " << f << " joint " << j;
                        }
                    }
                    // The evaluation at the frame's phase: one frame with
                    // weight 0 or 1, up to the phase's own rounding.
                    std::vector<glm::mat4> evaluated;
                    evaluateBakedPalette(baked, bakedClipIndex(uint32_t(i)), float(f) / float(frames - 1), evaluated);
                    const std::vector<glm::mat4> atFrame = posePalette(asset, &clip, t, false);
                    for (uint32_t j = 0; j < record.frames.z; ++j) {
                        EXPECT_LE(maxMatrixDifference(evaluated[j], atFrame[j]), 1e-6f)
                            << asset.name << " clip " << i << " frame " << f;
                    }
                }
            }
        }
    }
}

// Between frames the blend follows the chord, not the arc. The bounds are
// about 1.5 to 3 times the errors measured here (docs/CHARACTERS.md has them,
// and the generated creatures'), and the error must fall about as 1 / rate^2.
TEST(BakedAnimation, BlendBetweenFramesStaysNearThePose) {
    const CharacterAsset leg = makeLeg();
    const float legError30 = maxRelativeCageError(leg, bakeAnimation(leg), 0, 997);
    const float legError60 = maxRelativeCageError(leg, bakeAnimation(leg, {60.0f, true}), 0, 997);
    EXPECT_LT(legError30, 4e-3f); // 0.4% of the model's size (measured 0.24%)
    EXPECT_GT(legError30, 0.0f);
    EXPECT_GT(legError30 / legError60, 3.0f); // >= 4 for a 1 / rate^2 error
    std::printf("[          ] leg walk: max cage error %.3g (30 Hz), %.3g (60 Hz) of the model's size\n",
                double(legError30), double(legError60));

    // The tube's nod ends away from where it starts: it is a one-shot clip,
    // baked without the loop (a loop would blend its end back to its start
    // over the last frame interval, as Pose's own wrap jumps there).
    const CharacterAsset tube = test::makeTestCharacter();
    const float bendError = maxRelativeCageError(tube, bakeAnimation(tube), 0, 997);
    const float nodError = maxRelativeCageError(tube, bakeAnimation(tube, {30.0f, false}), 2, 997);
    EXPECT_LT(bendError, 1.5e-4f); // measured 6.8e-5
    EXPECT_LT(nodError, 2e-5f);    // measured 6.2e-6
    std::printf("[          ] tube: max cage error %.3g (bend), %.3g (nod) of the model's size\n", double(bendError),
                double(nodError));
}

TEST(BakedAnimation, LoopingWrapIsContinuous) {
    const CharacterAsset leg = makeLeg();
    const BakedAnimation baked = bakeAnimation(leg);
    const uint32_t walk = bakedClipIndex(0);
    const shader::BakedClip& record = baked.clips[walk];
    // The last frame repeats the first exactly.
    const size_t frameTexels = size_t(record.frames.z) * TS_BAKED_JOINT_TEXELS;
    for (size_t i = 0; i < frameTexels; ++i) {
        EXPECT_EQ(baked.rows[record.frames.x + i],
                  baked.rows[record.frames.x + (record.frames.y - 1) * frameTexels + i]);
    }
    // Across the wrap the palette moves no more than within the clip: compare
    // the step over the seam with a step of the same size mid-clip.
    std::vector<glm::mat4> before, after, zero, one, mid0, mid1;
    const float step = 1e-3f;
    evaluateBakedPalette(baked, walk, 1.0f - step / 2.0f, before);
    evaluateBakedPalette(baked, walk, 1.0f + step / 2.0f, after);
    evaluateBakedPalette(baked, walk, 0.0f, zero);
    evaluateBakedPalette(baked, walk, 1.0f, one);
    evaluateBakedPalette(baked, walk, 0.5f - step / 2.0f, mid0);
    evaluateBakedPalette(baked, walk, 0.5f + step / 2.0f, mid1);
    float seamStep = 0.0f, midStep = 0.0f;
    for (size_t j = 0; j < before.size(); ++j) {
        seamStep = std::max(seamStep, maxMatrixDifference(before[j], after[j]));
        midStep = std::max(midStep, maxMatrixDifference(mid0[j], mid1[j]));
        EXPECT_EQ(zero[j], one[j]);
    }
    EXPECT_LT(seamStep, 0.02f);
    EXPECT_LT(seamStep, 2.0f * midStep + 1e-5f);
    // And the pose itself agrees across the wrap (the clip's keys loop).
    const std::vector<glm::mat4> exactEnd = posePalette(leg, &leg.clips[0], leg.clips[0].duration(), false);
    for (size_t j = 0; j < zero.size(); ++j) EXPECT_LE(maxMatrixDifference(exactEnd[j], zero[j]), 1e-5f);
}

TEST(BakedAnimation, NonLoopingClipsClamp) {
    const CharacterAsset leg = makeLeg();
    const BakedAnimation baked = bakeAnimation(leg, {30.0f, false});
    const uint32_t walk = bakedClipIndex(0);
    EXPECT_EQ(baked.clips[walk].frames.w, 0u);
    std::vector<glm::mat4> late, end, early, start;
    evaluateBakedPalette(baked, walk, 1.7f, late);
    evaluateBakedPalette(baked, walk, 1.0f, end);
    evaluateBakedPalette(baked, walk, -0.3f, early);
    evaluateBakedPalette(baked, walk, 0.0f, start);
    EXPECT_EQ(late, end);
    EXPECT_EQ(early, start);
    const std::vector<glm::mat4> exactEnd = posePalette(leg, &leg.clips[0], leg.clips[0].duration(), false);
    for (size_t j = 0; j < end.size(); ++j) EXPECT_LE(maxMatrixDifference(exactEnd[j], end[j]), 1e-6f);
}

TEST(BakedAnimation, RestPoseForEveryCharacter) {
    CharacterAsset still = test::makeTestCharacter();
    still.clips.clear();
    const BakedAnimation baked = bakeAnimation(still);
    ASSERT_EQ(baked.clips.size(), 1u);
    EXPECT_EQ(baked.clips[kBakedRestPose].frames, glm::uvec4(0u, 1u, 3u, 1u));
    EXPECT_EQ(baked.texelCount(), 3u * TS_BAKED_JOINT_TEXELS);
    EXPECT_EQ(baked.bytes(), 9u * 16u + 32u);
    const std::vector<glm::mat4> rest = posePalette(still, nullptr, 0.0f);
    for (float phase : {0.0f, 0.3f, 1.0f, -2.5f, 1e6f, NAN}) {
        std::vector<glm::mat4> palette;
        evaluateBakedPalette(baked, kBakedRestPose, phase, palette);
        EXPECT_EQ(palette, rest) << phase;
    }
    // A character with clips has the same rest pose at clip 0.
    std::vector<glm::mat4> palette;
    evaluateBakedPalette(bakeAnimation(test::makeTestCharacter()), kBakedRestPose, 0.6f, palette);
    EXPECT_EQ(palette, rest);
}

TEST(BakedAnimation, CombineOffsetsClipsAndCharacters) {
    const CharacterAsset tube = test::makeTestCharacter();
    const CharacterAsset leg = makeLeg();
    CharacterAsset still = tube;
    still.clips.clear();
    const BakedAnimation parts[] = {bakeAnimation(tube), bakeAnimation(leg), bakeAnimation(still)};
    const BakedAnimation crowd = combine(parts);
    // tube: 4 clips, leg: 2, still: 1.
    EXPECT_EQ(crowd.characterClipBase, (std::vector<uint32_t>{0u, 4u, 6u}));
    EXPECT_EQ(crowd.clips.size(), 7u);
    EXPECT_EQ(crowd.texelCount(), parts[0].texelCount() + parts[1].texelCount() + parts[2].texelCount());
    EXPECT_EQ(crowd.bytes(), parts[0].bytes() + parts[1].bytes() + parts[2].bytes());
    EXPECT_EQ(crowd.globalClip(1, bakedClipIndex(0)), 5u);
    EXPECT_EQ(crowd.globalClip(2, kBakedRestPose), 6u);
    EXPECT_EQ(crowd.clips[5].frames.x, parts[0].texelCount() + parts[1].clips[1].frames.x);
    EXPECT_EQ(crowd.clips[6].frames.x, parts[0].texelCount() + parts[1].texelCount());

    // Every character's every clip evaluates as it did alone.
    for (uint32_t c = 0; c < 3; ++c) {
        for (uint32_t k = 0; k < parts[c].clips.size(); ++k) {
            for (float phase : {0.0f, 0.2137f, 0.5f, 0.99f}) {
                std::vector<glm::mat4> alone, combined;
                evaluateBakedPalette(parts[c], k, phase, alone);
                evaluateBakedPalette(crowd, crowd.globalClip(c, k), phase, combined);
                EXPECT_EQ(alone, combined) << c << " " << k << " " << phase;
            }
        }
    }

    // Combining a combined buffer flattens the characters.
    const BakedAnimation nested[] = {crowd, bakeAnimation(leg)};
    const BakedAnimation bigger = combine(nested);
    EXPECT_EQ(bigger.characterClipBase, (std::vector<uint32_t>{0u, 4u, 6u, 7u}));
    EXPECT_EQ(bigger.clips[bigger.globalClip(3, bakedClipIndex(0))].frames.x,
              crowd.texelCount() + parts[1].clips[1].frames.x);
    EXPECT_TRUE(combine({}).rows.empty());
}

// Baked vertex animation (the crowd's middle and far tiers): every frame's
// vertices are the cage skinned with that frame's baked matrices, in the
// 128-bit vertex; blending two frames' positions is skinning with the
// blended matrices, up to the format's quantisation.
TEST(BakedVertices, FramesAreTheSkinnedCageAndBlendsMatchTheMatrixBlend) {
    const CharacterAsset leg = makeLeg();
    const BakedAnimation baked = bakeAnimation(leg);
    // A box holding the leg in every pose (it swings 0.5 rad from a 1 m hip).
    const glm::vec3 lo(-1.5f, -1.0f, -1.5f), hi(1.5f, 2.0f, 1.5f);
    const PackingRange range{lo, hi, glm::vec2(0.0f), glm::vec2(1.0f)};
    std::vector<glm::uvec4> texels;
    const std::vector<uint32_t> first = appendBakedVertices(leg.cage, baked, 0, uint32_t(baked.clips.size()), range,
                                                            texels);
    ASSERT_EQ(first.size(), baked.clips.size());
    const size_t n = leg.cage.vertices.size();
    const uint32_t walk = bakedClipIndex(0);
    const shader::BakedClip& clip = baked.clips[walk];
    EXPECT_EQ(texels.size(), size_t(first.back()) + size_t(baked.clips.back().frames.y) * n);
    // The format's step: a 16-bit grid over the box.
    const float step = glm::length(hi - lo) / 65535.0f;
    auto unpack = [&](uint32_t frame, size_t v) {
        return shader::tsUnpackPosition(texels[first[walk] + frame * n + v], lo, hi);
    };
    std::vector<glm::mat4> palette;
    float worstFrame = 0.0f, worstBlend = 0.0f;
    for (uint32_t f = 0; f < clip.frames.y; ++f) {
        // A phase that lands on frame f exactly gives the baked matrices.
        evaluateBakedPalette(baked, walk, float(f) / float(clip.frames.y - 1), palette);
        for (size_t v = 0; v < n; ++v)
            worstFrame = std::max(worstFrame, glm::length(unpack(f, v) - skinVertex(leg.cage.vertices[v], palette).position));
    }
    for (uint32_t f = 0; f + 1 < clip.frames.y; ++f) {
        const float w = 0.3f;
        evaluateBakedPalette(baked, walk, (float(f) + w) / float(clip.frames.y - 1), palette);
        for (size_t v = 0; v < n; ++v) {
            const glm::vec3 blended = glm::mix(unpack(f, v), unpack(f + 1, v), w);
            worstBlend = std::max(worstBlend, glm::length(blended - skinVertex(leg.cage.vertices[v], palette).position));
        }
    }
    std::cout << "[baked vertices] worst at frames " << worstFrame << " m, between frames " << worstBlend
              << " m (the format's step " << step << " m)\n";
    EXPECT_LE(worstFrame, 2.0f * step);
    EXPECT_LE(worstBlend, 2.0f * step);
}
