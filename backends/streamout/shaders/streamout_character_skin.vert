#version 450
// streamout pass 1 for characters (the paper's DirectX 10 two-pass method:
// "stream output from vertex shaders"): each cage vertex is skinned once and
// streamed out as the 128-bit compressed vertex; the rasterizer is off. The
// tessellation pass then maps the stream-out buffer as a shader resource
// (a texel buffer) and loads one vertex per superprimitive corner.
#extension GL_GOOGLE_include_directive : require
#include "character_common.glsl"

layout(location = 0) in vec4 inPositionU;
layout(location = 1) in vec4 inNormalV;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in uvec4 inJoints;
layout(location = 4) in vec4 inWeights;

layout(xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16, location = 0) out uvec4 outPacked;

void main() {
    CharacterVertex v;
    v.positionU = inPositionU;
    v.normalV = inNormalV;
    v.tangent = inTangent;
    v.joints = inJoints;
    v.weights = inWeights;
    outPacked = tsCompressCageSample(tsSkinCageVertex(v));
    // Nothing is rasterized, but a point-list pipeline must still write both.
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
