#version 450
// r2vb pass 1 for characters (the paper's DirectX 9 two-pass method: "R2VB
// and pixel shaders"): one point per cage vertex, placed on texel
// gl_VertexIndex of an RGBA32UI render target; the vertex is skinned here
// and compressed to the 128-bit format, and the fragment writes it out. The
// target is then copied to a buffer that the tessellation pass fetches from.
#extension GL_GOOGLE_include_directive : require
#include "character_common.glsl"
#include "r2vb_points.glsl"

// The bind-pose cage as an ordinary vertex stream (CharacterVertex).
layout(location = 0) in vec4 inPositionU;
layout(location = 1) in vec4 inNormalV;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in uvec4 inJoints;
layout(location = 4) in vec4 inWeights;

layout(location = 0) flat out uvec4 outPacked;

void main() {
    CharacterVertex v;
    v.positionU = inPositionU;
    v.normalV = inNormalV;
    v.tangent = inTangent;
    v.joints = inJoints;
    v.weights = inWeights;
    outPacked = tsCompressCageSample(tsSkinCageVertex(v));
    gl_Position = r2vbTexelPosition(uint(gl_VertexIndex));
    gl_PointSize = 1.0;
}
