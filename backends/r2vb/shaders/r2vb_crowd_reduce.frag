#version 450
// Pass crowd.pyramid (r2vb): one full-region draw per level; each texel of
// level pc.target.z is the sum of its 2 x 2 texels of the level below (per
// tier, the elements of its block), read from the other parity's atlas.
#extension GL_GOOGLE_include_directive : require
#include "r2vb_crowd.glsl"

layout(set = 0, binding = R2VB_CROWD_BINDING_SOURCE) uniform usampler2D uSource;

layout(location = 0) out uvec4 outSum;

void main() {
    uint level = pc.target.z;
    uvec2 texel = uvec2(gl_FragCoord.xy) - r2vbPyramidOrigin(level, pc.pyramid.x);
    ivec2 below = ivec2(r2vbPyramidOrigin(level - 1u, pc.pyramid.x) + texel * 2u);
    outSum = texelFetch(uSource, below, 0) + texelFetch(uSource, below + ivec2(1, 0), 0) +
             texelFetch(uSource, below + ivec2(0, 1), 0) + texelFetch(uSource, below + ivec2(1, 1), 0);
}
