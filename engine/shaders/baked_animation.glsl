// baked_animation.glsl: a crowd instance's skinning matrix from the baked
// clips (shared/BakedAnimation.h has the layout; character::bakeAnimation
// writes the buffer and character::evaluateBakedJoint is this function on the
// CPU, for the null backend and the tests).
//
// The matrix is the linear blend of the two baked frames around the phase.
// Blending affine matrices component-wise is what GPU crowd renderers do: it
// is exact at the frames, and between them it follows the chord instead of
// the arc, so a point rotating at w rad/s at distance r from its bone's pivot
// comes inward by up to r * (1 - cos(w / (2 fps))) ~ r w^2 / (8 fps^2), and
// the blended matrix is not quite a rotation (its scale dips by the same
// factor at mid-frame). docs/CHARACTERS.md gives the figure measured on the
// generated creatures.
#ifndef BAKED_ANIMATION_GLSL
#define BAKED_ANIMATION_GLSL
#include "tessera/shaders/BakedAnimation.h"

// Row r of a baked matrix from its three texels to a mat4 (GLSL's mat4 takes
// columns; the fourth row of an affine matrix is (0, 0, 0, 1)).
mat4 tsBakedRowsToMat4(vec4 r0, vec4 r1, vec4 r2) {
    return mat4(vec4(r0.x, r1.x, r2.x, 0.0), vec4(r0.y, r1.y, r2.y, 0.0), vec4(r0.z, r1.z, r2.z, 0.0),
                vec4(r0.w, r1.w, r2.w, 1.0));
}

// `joint`'s skinning matrix in `clip` at `phase` (0 at the clip's first
// frame, 1 at its last; wrapped for looping clips, clamped for the others).
// `bakedMatrices` is the RGBA32F texel buffer of every baked clip.
mat4 tsBakedJoint(samplerBuffer bakedMatrices, BakedClip clip, float phase, uint joint) {
    uint frame0, frame1;
    float w = tsBakedFramePair(clip, phase, frame0, frame1);
    int a = int(tsBakedJointTexel(clip, frame0, joint));
    int b = int(tsBakedJointTexel(clip, frame1, joint));
    vec4 r0 = mix(texelFetch(bakedMatrices, a), texelFetch(bakedMatrices, b), w);
    vec4 r1 = mix(texelFetch(bakedMatrices, a + 1), texelFetch(bakedMatrices, b + 1), w);
    vec4 r2 = mix(texelFetch(bakedMatrices, a + 2), texelFetch(bakedMatrices, b + 2), w);
    return tsBakedRowsToMat4(r0, r1, r2);
}

#endif
