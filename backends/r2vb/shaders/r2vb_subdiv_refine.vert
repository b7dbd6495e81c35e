#version 450
// subdiv.refine on r2vb (the first paper's DirectX 9 recirculation): one
// point per refined point of a subdivision surface (control points, then
// corner LOD points), placed on texel gl_VertexIndex of an RGBA32F render
// target; the vertex shader sums the point's stencil over this frame's cage
// (subdiv_refine.glsl, the sum every backend makes) and the pixel shader
// writes it. The target is then copied to the refined points (R2VB), which
// the command pass and the draw read by vertex texture fetch.
#extension GL_GOOGLE_include_directive : require
#include "subdiv_refine.glsl"
#include "r2vb_points.glsl"

layout(location = 0) flat out vec4 outPoint;

void main() {
    outPoint = tsSubdivRefinePoint(uint(gl_VertexIndex));
    gl_Position = r2vbTexelPosition(uint(gl_VertexIndex));
    gl_PointSize = 1.0;
}
