// BakedAnimation.h: clips baked at load time into one buffer of joint
// matrices, for crowds (character::bakeAnimation writes it; the GPU reads it
// through baked_animation.glsl, the null backend and the tests through
// character::evaluateBakedJoint).
//
// The buffer is an RGBA32F texel buffer: every joint matrix is the 3x4
// affine part of the skinning matrix (global(node) * inverseBind), row-major,
// three texels (48 bytes) per joint:
//
//   texel first + (frame * joints + joint) * 3 + r  =  row r of the matrix,
//                                                      (m[0][r], m[1][r], m[2][r], m[3][r]) in glm's m[column][row]
//
// A clip's frames follow each other, every frame holding all the character's
// joints; clips of every character follow each other in one buffer.
// An RGBA32F uniform texel buffer is what every backend can read, the
// D3D9-style one included (it has texel fetch in vertex shaders only).
//
// A drawn instance carries (clip, phase): the index of a BakedClip record and
// the phase in its cycle, 0 at the first frame and 1 at the last. Frames are
// evenly spaced over the clip (frame f at f / (frames - 1) of the duration),
// so the frame pair and the blend weight depend on the phase alone and the
// same instance data plays at any speed. tsBakedFramePair() is that
// selection, written once for C++ and GLSL so both pick the same frames.
#ifndef TESSERA_BAKED_ANIMATION_H
#define TESSERA_BAKED_ANIMATION_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

// RGBA32F texels per joint matrix (the three rows of the 3x4 affine part).
#define TS_BAKED_JOINT_TEXELS 3u

// One baked clip (32 bytes).
//   frames: x = first texel (row) of frame 0, joint 0; y = frame count (>= 1);
//           z = joints per frame; w = 1 for a looping clip
//   timing: x = duration (s); y = 1 / duration, the phase per second (0 for a
//           clip without duration); z = the rate actually baked,
//           (frames - 1) / duration; w = 0 (an instanced crowd's GPU copy: the
//           clip's first impostor layer, CrowdImpostor.h)
struct BakedClip {
    uvec4 frames;
    vec4 timing;
};
TS_CHECK_SIZE(BakedClip, 32)

/// The two frames around `phase` and the weight of the second: the baked
/// matrix is mix(frame0, frame1, weight). A looping clip wraps the phase
/// into [0, 1) (its last frame repeats its first, so the wrap is seamless);
/// any other clamps it to [0, 1]. A one-frame clip (a rest pose) returns
/// frame 0 twice.
TS_INLINE float tsBakedFramePair(BakedClip clip, float phase, TS_OUT(uint) frame0, TS_OUT(uint) frame1) {
    float p = clip.frames.w != 0u ? phase - floor(phase) : clamp(phase, 0.0f, 1.0f);
    uint last = clip.frames.y > 0u ? clip.frames.y - 1u : 0u;
    float x = p * float(last);
    uint f = uint(max(floor(x), 0.0f));
    // x reaches `last` at phase 1 (or at a phase just below 1 that rounds up):
    // keep the pair inside the clip and let the weight reach 1.
    uint lastPair = last > 0u ? last - 1u : 0u;
    f = min(f, lastPair);
    frame0 = f;
    frame1 = min(f + 1u, last);
    return last > 0u ? clamp(x - float(f), 0.0f, 1.0f) : 0.0f;
}

/// The texel holding row 0 of `joint`'s matrix in `frame` of `clip`.
TS_INLINE uint tsBakedJointTexel(BakedClip clip, uint frame, uint joint) {
    return clip.frames.x + (frame * clip.frames.z + joint) * TS_BAKED_JOINT_TEXELS;
}

TS_NAMESPACE_END

#endif
