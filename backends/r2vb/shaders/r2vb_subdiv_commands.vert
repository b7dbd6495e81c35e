#version 450
// subdiv.commands on r2vb: one point per tessellation domain of a
// subdivision surface (record r = domain r = gl_VertexIndex). Its levels
// come from tsSubdivLevels, the function hulldomain's hull stage calls,
// reading the refined LOD points by vertex texture fetch, clamped to the
// emulated tessellator's [1, TS_EMU_MAX_LEVEL]; the emulated tessellator's
// control logic turns them into five indirect draw commands (zero when the
// domain is culled). Everything goes to render targets at texel r
// (r2vb_commands.frag writes them); the R2VB step copies them to the record
// texel buffer and the indirect buffer.
#extension GL_GOOGLE_include_directive : require
#include "subdiv_levels.glsl"
#include "emulated_tess.glsl"
#include "r2vb_points.glsl"

layout(location = 0) flat out vec4 outOuter;
layout(location = 1) flat out vec4 outInner;
layout(location = 2) flat out uvec4 outCommands[TS_EMU_PIECES];

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
    gl_Position = r2vbTexelPosition(domain);
    gl_PointSize = 1.0;
}
