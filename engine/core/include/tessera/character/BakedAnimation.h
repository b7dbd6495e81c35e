#pragma once
/// @file BakedAnimation.h
/// Animation for crowds: every clip of a character sampled once, at load
/// time, into one buffer of joint matrices, so that drawing 10,000 to 65,000
/// animated instances needs no per-agent palette on the CPU. Each instance
/// carries (clip, phase); the GPU fetches the two baked frames around the
/// phase and blends them (engine/shaders/baked_animation.glsl).
/// Layout: engine/core/include/tessera/shaders/BakedAnimation.h. docs/CHARACTERS.md,
/// "Baked animation for crowds", has the memory and error figures.

#include "tessera/character/CharacterAsset.h"

// The layout shared with GLSL (engine/core/include/tessera/shaders/BakedAnimation.h). Angle
// brackets: a quoted name would find this very file first.
#include "tessera/shaders/BakedAnimation.h"

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace tessera::character {

/// How bakeAnimation samples.
struct BakeSettings {
    /// The least sample rate. A clip of duration d gets
    /// frames = max(2, ceil(d * rate) + 1), evenly spaced from 0 to d, so the
    /// rate actually baked ((frames - 1) / d, BakedClip::timing.z) is this or
    /// slightly more. The interpolation error falls as 1 / rate^2.
    float framesPerSecond = 30.0f;
    /// Bake clips as loops: the last frame repeats the first, so the blend
    /// wraps seamlessly from the end to the start. Without, clips clamp.
    /// glTF has no loop flag; the demo loops every clip.
    bool loop = true;
};

/// The baked clip index of the rest pose within one character's clips.
inline constexpr uint32_t kBakedRestPose = 0;

/// The baked clip index (within its character) of `CharacterAsset::clips[assetClip]`:
/// the rest pose comes first, so every character, with clips or without,
/// has a baked clip 0 to draw.
constexpr uint32_t bakedClipIndex(uint32_t assetClip) {
    return assetClip + 1;
}

/// Baked clips of one or several characters, and the buffer they index.
///
/// `rows` is the RGBA32F texel buffer to upload as it is; `clips` the
/// BakedClip records (a uniform or storage array). After combine(), a crowd
/// mixing several characters in one instanced draw addresses character c's
/// local clip k (kBakedRestPose, or bakedClipIndex(i)) as the global record
/// clips[characterClipBase[c] + k], i.e. globalClip(c, k).
struct BakedAnimation {
    /// Every clip's frames, joints and rows, contiguous (see the layout
    /// header): TS_BAKED_JOINT_TEXELS texels per joint matrix.
    std::vector<glm::vec4> rows;
    /// The clip records. For one character: [rest pose, clips[0], clips[1], ...].
    std::vector<shader::BakedClip> clips;
    /// The first global clip record of each character: {0} for one baked
    /// character; one entry per character after combine().
    std::vector<uint32_t> characterClipBase;

    /// The global BakedClip index of `character`'s local clip `localClip`.
    /// Asserts both are in range.
    uint32_t globalClip(uint32_t character, uint32_t localClip) const;

    /// Texels in `rows` (to check against the device's maxTexelBufferElements;
    /// Vulkan guarantees 65,536).
    size_t texelCount() const { return rows.size(); }

    /// The bytes the GPU holds: the texel buffer plus the clip records.
    size_t bytes() const { return rows.size() * sizeof(glm::vec4) + clips.size() * sizeof(shader::BakedClip); }
};

/// Bakes every clip of `asset` with character::Pose (reset, apply at the
/// frame's time, computeGlobals, palette) and stores each frame's palette,
/// one 3x4 matrix per CageMesh::bindings entry. Clip 0 is the rest pose (one
/// frame); clip bakedClipIndex(i) is asset.clips[i]. The baked rows equal
/// Pose::palette's matrices exactly at every frame. Asserts that
/// `settings.framesPerSecond` is positive and finite and that the skeleton is
/// parent-first (as Pose does).
BakedAnimation bakeAnimation(const CharacterAsset& asset, const BakeSettings& settings = {});

/// Several characters' baked animations in one buffer, in the order given:
/// rows are appended, every clip's first texel is moved by the rows before
/// it, and characterClipBase gets one entry per character of each part (a
/// part may itself be combined). Characters may differ in joint count.
BakedAnimation combine(std::span<const BakedAnimation> parts);

/// The phase (what an instance carries) of `seconds` into `clip`: seconds /
/// duration, not wrapped (the evaluation wraps or clamps); 0 for a clip
/// without duration.
float bakedPhase(const shader::BakedClip& clip, float seconds);

/// `joint`'s matrix in global clip `clip` at `phase`, as tsBakedJoint
/// computes it on the GPU: the same frames and weight (tsBakedFramePair),
/// rows blended with mix(). Equal to the GPU's up to float rounding; for the
/// null backend and tests. Asserts clip and joint are in range.
glm::mat4 evaluateBakedJoint(const BakedAnimation& baked, uint32_t clip, float phase, uint32_t joint);

/// The whole palette of global clip `clip` at `phase` (its joints-per-frame
/// matrices) into `out`, as evaluateBakedJoint.
void evaluateBakedPalette(const BakedAnimation& baked, uint32_t clip, float phase, std::vector<glm::mat4>& out);

} // namespace tessera::character
