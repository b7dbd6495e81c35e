#version 450
// The baked animation fetch (baked_animation.glsl) against its C++ twin,
// character::evaluateBakedJoint: one joint matrix per query, read from the
// RGBA32F texel buffer every backend reads (tests/gpu/baked_animation_test.cpp
// compares).
#extension GL_GOOGLE_include_directive : require
#include "baked_animation.glsl"
#include "../support/BakedAnimationTestLayout.h"

layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform samplerBuffer uBakedMatrices;
layout(std430, set = 0, binding = 1) readonly buffer Clips {
    BakedClip clips[];
};
layout(std430, set = 0, binding = 2) readonly buffer Queries {
    TsBakedTestQuery queries[];
};
layout(std430, set = 0, binding = 3) writeonly buffer Outputs {
    mat4 outputs[];
};
layout(push_constant) uniform Push {
    TsBakedTestParams params;
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count.x) return;
    TsBakedTestQuery q = queries[i];
    outputs[i] = tsBakedJoint(uBakedMatrices, clips[q.clipJoint.x], q.phase.x, q.clipJoint.y);
}
