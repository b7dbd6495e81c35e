#version 450
// The refine pass of the backends with compute (hulldomain, meshshader):
// every control point and corner point of a subdivision surface from this
// frame's cage, one invocation each.
#extension GL_GOOGLE_include_directive : require
#include "subdiv_refine.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = TS_BINDING_SUBDIV_POINTS) writeonly buffer PointsBlock {
    vec4 points[];
};
layout(push_constant) uniform Refine {
    uint count;
} refine;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= refine.count) return;
    points[i] = tsSubdivRefinePoint(i);
}
