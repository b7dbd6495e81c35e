#version 450
// One triangle covering the viewport at the far plane (depth 1, which the
// main pass's LESS_OR_EQUAL test passes only where nothing was drawn), with
// the far-plane point under each corner in homogeneous world coordinates.
// That point is affine in screen space, so interpolating it is exact and the
// fragment shader gets its view ray with no per-pixel matrix.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"

layout(location = 0) out vec4 outFarPoint;

void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    vec2 ndc = corner * 2.0 - 1.0;
    gl_Position = vec4(ndc, 1.0, 1.0);
    outFarPoint = inverse(frame.viewProjection) * vec4(ndc, 1.0, 1.0);
}
