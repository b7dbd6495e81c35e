#version 450
// DrawAuto test, capture: one point per vertex streams its index out
// (transform feedback, 4 bytes a vertex); nothing is rasterised.
layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 4) out uint capturedIndex;

void main() {
    capturedIndex = uint(gl_VertexIndex);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
