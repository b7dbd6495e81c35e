#version 450
// The base-surface patch evaluation of subdiv_patch.glsl (OpenSubdiv's GLSL
// basis) at given (patch, s, t) samples, for the test against the CPU.
#extension GL_GOOGLE_include_directive : require
#include "subdiv_patch.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Points { vec4 points[]; };   // control points, xyz
layout(std430, set = 0, binding = 1) readonly buffer Indices { uint indices[]; };  // patch point indices
layout(std430, set = 0, binding = 2) readonly buffer Patches { uvec4 patches[]; }; // type, first index, param words
layout(std430, set = 0, binding = 3) readonly buffer Samples { vec4 samples[]; };  // x: patch (bits), yz: s, t
layout(std430, set = 0, binding = 4) writeonly buffer Results { vec4 results[]; }; // P, dP/du, dP/dv per sample
layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    vec4 sample_ = samples[i];
    uvec4 patch_ = patches[floatBitsToUint(sample_.x)];
    float wP[20], wDu[20], wDv[20];
    int n = tsSubdivBasis(patch_.x, uvec3(patch_.z, patch_.w, 0u), sample_.yz, wP, wDu, wDv);
    vec3 p = vec3(0.0), du = vec3(0.0), dv = vec3(0.0);
    for (int k = 0; k < n; ++k) {
        vec3 c = points[indices[patch_.y + uint(k)]].xyz;
        p += wP[k] * c;
        du += wDu[k] * c;
        dv += wDv[k] * c;
    }
    results[3u * i] = vec4(p, 1.0);
    results[3u * i + 1u] = vec4(du, 0.0);
    results[3u * i + 2u] = vec4(dv, 0.0);
}
