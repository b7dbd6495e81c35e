#include "tessera/character/BakedAnimation.h"

#include "tessera/character/Pose.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace tessera::character {

namespace {

// Row r of the affine part of m, as the layout stores it (glm is m[column][row]).
glm::vec4 matrixRow(const glm::mat4& m, int r) {
    return {m[0][r], m[1][r], m[2][r], m[3][r]};
}

void appendPalette(const std::vector<glm::mat4>& palette, std::vector<glm::vec4>& rows) {
    for (const glm::mat4& m : palette) {
        for (int r = 0; r < 3; ++r) rows.push_back(matrixRow(m, r));
    }
}

uint32_t toTexelIndex(size_t n) {
    // The GPU addresses texels with int; a buffer this large would not fit any
    // device's maxTexelBufferElements anyway.
    assert(n <= static_cast<size_t>(std::numeric_limits<int32_t>::max()));
    return static_cast<uint32_t>(n);
}

// Frames for a clip of `duration` seconds: evenly spaced from 0 to duration,
// at least `rate` per second, at least 2. The small slack keeps a duration
// that is a whole number of frames in float (1.1 s at 30 Hz = 33.0000008)
// from gaining a frame it does not need.
uint32_t frameCount(float duration, float rate) {
    const double intervals = std::ceil(static_cast<double>(duration) * rate - 1e-3);
    assert(intervals < 1e7); // a clip of days: a content error, not a crowd clip
    return std::max(2u, static_cast<uint32_t>(std::max(intervals, 0.0)) + 1u);
}

} // namespace

uint32_t BakedAnimation::globalClip(uint32_t character, uint32_t localClip) const {
    assert(character < characterClipBase.size());
    const uint32_t index = characterClipBase[character] + localClip;
    [[maybe_unused]] const size_t end =
        character + 1 < characterClipBase.size() ? characterClipBase[character + 1] : clips.size();
    assert(index < end);
    return index;
}

BakedAnimation bakeAnimation(const CharacterAsset& asset, const BakeSettings& settings) {
    assert(settings.framesPerSecond > 0.0f && std::isfinite(settings.framesPerSecond));
    const uint32_t joints = static_cast<uint32_t>(asset.cage.bindings.size());
    BakedAnimation baked;
    baked.characterClipBase = {0};
    baked.clips.reserve(asset.clips.size() + 1);

    Pose pose(asset.skeleton);
    std::vector<glm::mat4> palette;

    // The rest pose: one frame, so a clip-less character (a static prop, a
    // model without animations) is drawn by the same instanced path.
    shader::BakedClip rest{};
    rest.frames = glm::uvec4(0u, 1u, joints, 1u);
    rest.timing = glm::vec4(0.0f);
    pose.reset();
    pose.computeGlobals();
    pose.palette(asset.cage, palette);
    appendPalette(palette, baked.rows);
    baked.clips.push_back(rest);

    for (const AnimationClip& clip : asset.clips) {
        const float duration = clip.duration();
        const uint32_t frames = frameCount(duration, settings.framesPerSecond);
        shader::BakedClip record{};
        record.frames = glm::uvec4(toTexelIndex(baked.rows.size()), frames, joints, settings.loop ? 1u : 0u);
        record.timing = duration > 0.0f ? glm::vec4(duration, 1.0f / duration, float(frames - 1) / duration, 0.0f)
                                        : glm::vec4(0.0f);
        const size_t firstRow = baked.rows.size();
        for (uint32_t f = 0; f < frames; ++f) {
            if (settings.loop && f + 1 == frames) {
                // The sample at `duration` would equal frame 0 only up to the
                // keys' own wrap; copying it makes the blend across the wrap
                // exactly continuous.
                const size_t count = size_t(joints) * TS_BAKED_JOINT_TEXELS;
                baked.rows.insert(baked.rows.end(), baked.rows.begin() + static_cast<std::ptrdiff_t>(firstRow),
                                  baked.rows.begin() + static_cast<std::ptrdiff_t>(firstRow + count));
                break;
            }
            // Computed in double so the last frame lands on `duration` exactly
            // and no frame drifts by accumulated rounding.
            const float t = static_cast<float>(static_cast<double>(duration) * f / (frames - 1));
            pose.reset();
            // t is inside [0, duration]: no wrap wanted (fmod would send the
            // last frame of a non-looping clip back to 0).
            pose.apply(clip, t, /*loop=*/false);
            pose.computeGlobals();
            pose.palette(asset.cage, palette);
            appendPalette(palette, baked.rows);
        }
        baked.clips.push_back(record);
    }
    toTexelIndex(baked.rows.size());
    return baked;
}

BakedAnimation combine(std::span<const BakedAnimation> parts) {
    BakedAnimation out;
    size_t rows = 0, clips = 0, characters = 0;
    for (const BakedAnimation& part : parts) {
        rows += part.rows.size();
        clips += part.clips.size();
        characters += part.characterClipBase.size();
    }
    out.rows.reserve(rows);
    out.clips.reserve(clips);
    out.characterClipBase.reserve(characters);
    for (const BakedAnimation& part : parts) {
        const uint32_t rowBase = toTexelIndex(out.rows.size());
        const uint32_t clipBase = static_cast<uint32_t>(out.clips.size());
        for (uint32_t base : part.characterClipBase) out.characterClipBase.push_back(clipBase + base);
        for (shader::BakedClip clip : part.clips) {
            clip.frames.x += rowBase;
            out.clips.push_back(clip);
        }
        out.rows.insert(out.rows.end(), part.rows.begin(), part.rows.end());
    }
    toTexelIndex(out.rows.size());
    return out;
}

float bakedPhase(const shader::BakedClip& clip, float seconds) {
    return seconds * clip.timing.y;
}

glm::mat4 evaluateBakedJoint(const BakedAnimation& baked, uint32_t clip, float phase, uint32_t joint) {
    assert(clip < baked.clips.size());
    const shader::BakedClip& record = baked.clips[clip];
    assert(joint < record.frames.z);
    // A NaN or infinite phase has no frame; the GPU's float-to-uint of it is
    // undefined too. Play the first frame rather than read out of range.
    if (!std::isfinite(phase)) phase = 0.0f;
    uint32_t frame0 = 0, frame1 = 0;
    const float w = shader::tsBakedFramePair(record, phase, frame0, frame1);
    const size_t a = shader::tsBakedJointTexel(record, frame0, joint);
    const size_t b = shader::tsBakedJointTexel(record, frame1, joint);
    assert(b + 2 < baked.rows.size() && a + 2 < baked.rows.size());
    // glm::mix is x * (1 - w) + y * w, GLSL's definition of mix().
    const glm::vec4 r0 = glm::mix(baked.rows[a], baked.rows[b], w);
    const glm::vec4 r1 = glm::mix(baked.rows[a + 1], baked.rows[b + 1], w);
    const glm::vec4 r2 = glm::mix(baked.rows[a + 2], baked.rows[b + 2], w);
    return glm::mat4(glm::vec4(r0.x, r1.x, r2.x, 0.0f), glm::vec4(r0.y, r1.y, r2.y, 0.0f),
                     glm::vec4(r0.z, r1.z, r2.z, 0.0f), glm::vec4(r0.w, r1.w, r2.w, 1.0f));
}

void evaluateBakedPalette(const BakedAnimation& baked, uint32_t clip, float phase, std::vector<glm::mat4>& out) {
    assert(clip < baked.clips.size());
    const uint32_t joints = baked.clips[clip].frames.z;
    out.resize(joints);
    for (uint32_t j = 0; j < joints; ++j) out[j] = evaluateBakedJoint(baked, clip, phase, j);
}

} // namespace tessera::character
