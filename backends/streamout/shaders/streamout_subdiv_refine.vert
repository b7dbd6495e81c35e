#version 450
// subdiv.refine on streamout (D3D10's "stream output from vertex shaders"):
// one invocation per refined point (control points, then corner LOD
// points), the stencil sum of subdiv_refine.glsl over this frame's cage,
// streamed out as one RGBA32F texel at the point's index; the rasterizer is
// off. The draw and the factor pass then read the stream-out buffer as a
// texel buffer (D3D10's Buffer<float4>.Load).
#extension GL_GOOGLE_include_directive : require
#include "subdiv_refine.glsl"

layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out vec4 outPoint;

void main() {
    outPoint = tsSubdivRefinePoint(uint(gl_VertexIndex));
    // Nothing is rasterized, but a point-list pipeline must still write both.
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
