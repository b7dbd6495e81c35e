#version 450
// Pass r2vb.commands: one point per visible patch (record r = its slot).
// Its outer levels arrive as a vertex stream, the factor target copied to a
// buffer (R2VB); the patch's own detail term and the inner levels follow the
// same rules as hulldomain's hull stage, and the emulated tessellator's
// control logic turns them into five indirect draw commands. Everything is
// written to render targets at texel r; the next R2VB step copies them to
// the record texel buffer and the indirect buffer.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#define TS_NO_LEVEL_BUFFERS
#include "terrain_tess.glsl"
#include "terrain_metric.glsl"
#include "emulated_tess.glsl"
#include "r2vb_points.glsl"

layout(std430, set = 0, binding = TS_BINDING_PATCH_ERROR) readonly buffer PatchErrors {
    float patchErrors[];
};

layout(location = 0) in vec4 inOuter; // the patch's four edge levels (R2VB stream)
layout(location = 1) in uint inPatch; // visible patch index

layout(location = 0) flat out vec4 outOuter;
layout(location = 1) flat out vec4 outInner;
layout(location = 2) flat out uvec4 outCommands[TS_EMU_PIECES];

void main() {
    uint record = uint(gl_VertexIndex);
    vec4 outer;
    vec2 inner;
    if (tess.mode.x == TS_TERRAIN_MODE_CONTINUOUS) {
        // One level for the draw (already clamped to [1, TS_EMU_MAX_LEVEL]);
        // the stream was not written this frame and is not read.
        outer = vec4(tess.levels.z);
        inner = vec2(tess.levels.z);
    } else {
        uint patches = tess.mode.z;
        vec2 corner = vec2(float(inPatch % patches), float(inPatch / patches));
        float own = terrainClampLevel(terrainPatchMetric(terrainSurfacePoint(corner),
                                                         terrainSurfacePoint(corner + vec2(1.0)), patchErrors[inPatch]));
        outer = inOuter;
        inner = terrainInnerLevels(outer, own);
    }
    outOuter = outer;
    outInner = vec4(inner, float(inPatch), 0.0);
    for (uint piece = 0u; piece < TS_EMU_PIECES; ++piece) outCommands[piece] = tsEmuCommand(outer, inner, piece, record);
    gl_Position = r2vbTexelPosition(record);
    gl_PointSize = 1.0;
}
