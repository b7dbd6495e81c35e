#version 450
// Pass-through evaluation: writes the tessellation coordinate of every
// emitted triangle's vertices to transform feedback. Built once per domain
// (TS_QUADS or not) and spacing (TS_SPACING).
#ifdef TS_QUADS
layout(quads, TS_SPACING, ccw) in;
#else
layout(triangles, TS_SPACING, ccw) in;
#endif
layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out vec4 outCoord;

void main() {
    outCoord = vec4(gl_TessCoord, 1.0);
    gl_Position = vec4(gl_TessCoord.xy, 0.0, 1.0);
}
