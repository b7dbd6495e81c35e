#version 450
// The whole evaluation the backends run per tessellated point
// (subdiv_eval.glsl's tsSubdivEvaluate: domain to ptex, the quadtree to
// Far's patch, OpenSubdiv's basis on the refined points, the owner rule on
// shared edges and corners) at given (domain, u, v) samples, for the test
// against OpenSubdiv on the CPU.
#extension GL_GOOGLE_include_directive : require
#include "subdiv_eval.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 50) readonly buffer Samples { vec4 samples[]; };  // x: domain (bits), yz: u, v
layout(std430, set = 0, binding = 51) writeonly buffer Results { vec4 results[]; }; // position, d/du, d/dv
layout(push_constant) uniform Push { uint count; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    vec4 s = samples[i];
    TsSubdivVertex v = tsSubdivEvaluate(floatBitsToUint(s.x), s.yz);
    results[3u * i] = vec4(v.position, 1.0);
    results[3u * i + 1u] = vec4(v.du, 0.0);
    results[3u * i + 2u] = vec4(v.dv, 0.0);
}
