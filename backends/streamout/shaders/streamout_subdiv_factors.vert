#version 450
// subdiv.factors on streamout: one invocation per tessellation domain of a
// subdivision surface (the vertex index; no vertex stream). Its levels come
// from tsSubdivLevels, the function hulldomain's hull stage calls, clamped
// to the emulated tessellator's [1, TS_EMU_MAX_LEVEL]; transform feedback
// writes the emulated tessellator's input (EmulatedDrawSource.h), record r =
// domain r:
//   buffer 0: the outer levels (records texel r),
//   buffer 1: (inner u, inner v, domain, 0) (records texel capacity + r),
//   buffer 2: its five tessellator commands, all zero when culled.
// Corner levels are per refined LOD point, so two domains sharing an edge
// compute its level from the same two values: no cracks.
#extension GL_GOOGLE_include_directive : require
#include "subdiv_levels.glsl"
#include "emulated_tess.glsl"

layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out vec4 outOuter;
layout(location = 1, xfb_buffer = 1, xfb_offset = 0, xfb_stride = 16) out vec4 outInner;
layout(location = 2, xfb_buffer = 2, xfb_offset = 0, xfb_stride = 80) out uvec4 outCommands[TS_EMU_PIECES];

void main() {
    uint domain = uint(gl_VertexIndex);
    vec4 outer;
    vec2 inner;
    bool drawn = tsSubdivLevels(domain, outer, inner);
    outer = clamp(outer, vec4(1.0), vec4(TS_EMU_MAX_LEVEL));
    inner = clamp(inner, vec2(1.0), vec2(TS_EMU_MAX_LEVEL));
    outOuter = outer;
    outInner = vec4(inner, float(domain), 0.0);
    for (uint piece = 0u; piece < TS_EMU_PIECES; ++piece)
        outCommands[piece] = drawn ? tsEmuCommand(outer, inner, piece, domain) : uvec4(0u);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
