#version 450
// streamout.factors: one invocation per surviving patch (draw-auto over the
// cull pass's stream output, so its vertex index is the record). It loads the
// patch's corners from the cage buffer, computes the four edge levels and the
// inner levels exactly as hulldomain's factor pre-pass and hull stage do, and
// streams out the emulated tessellator's input (EmulatedTerrainBackend.h):
//   buffer 0: the record's outer levels (records texel r),
//   buffer 1: (inner u, inner v, patch, 0) (records texel capacity + r),
//   buffer 2: its five tessellator commands (indirect draws).
//
// No level is stored per edge: each patch evaluates its own four. An edge is
// shared by two patches that walk it in opposite directions, so each swaps the
// endpoints into vertex-ID order first (the first paper's vertex-ID swap): both
// then feed the metric identical inputs in the identical order, through one
// non-unrolled loop body, and get bit-identical levels. No cracks.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#define TS_NO_LEVEL_BUFFERS
#include "terrain_tess.glsl"
#include "terrain_metric.glsl"
#include "emulated_tess.glsl"
#include "streamout_bindings.h"
#include "streamout_cage.glsl"

layout(std430, set = 0, binding = TS_BINDING_EDGE_ERROR) readonly buffer EdgeErrors {
    float edgeErrors[];
};
layout(std430, set = 0, binding = TS_BINDING_PATCH_ERROR) readonly buffer PatchErrors {
    float patchErrors[];
};

layout(location = 0) in uint inPatch;

layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out vec4 outOuter;
layout(location = 1, xfb_buffer = 1, xfb_offset = 0, xfb_stride = 16) out vec4 outInner;
layout(location = 2, xfb_buffer = 2, xfb_offset = 0, xfb_stride = 80) out uvec4 outCommands[TS_EMU_PIECES];

void adaptiveLevels(uint patchIndex, out vec4 outer, out vec2 inner) {
    uint patches = tess.mode.z;
    uint x = patchIndex % patches;
    uint z = patchIndex / patches;
    // Corners in winding order; side s (Vulkan quad outer-level order) runs
    // from corner (s + 3) % 4 to corner s.
    uint corners[4] = uint[4](soGridVertex(x, z), soGridVertex(x + 1u, z), soGridVertex(x + 1u, z + 1u),
                              soGridVertex(x, z + 1u));
    float levels[4];
    [[dont_unroll]] for (uint side = 0u; side < 4u; ++side) {
        vec4 a = soCagePoint(corners[(side + 3u) & 3u]);
        vec4 b = soCagePoint(corners[side]);
        if (a.w > b.w) {
            vec4 t = a;
            a = b;
            b = t;
        }
        float error = edgeErrors[tsPatchEdge(x, z, side, patches)];
        levels[side] = terrainClampLevel(terrainEdgeMetric(a.xyz, b.xyz, error));
    }
    outer = vec4(levels[0], levels[1], levels[2], levels[3]);
    vec3 first = soCagePoint(corners[0]).xyz;
    vec3 opposite = soCagePoint(corners[2]).xyz;
    float own = terrainClampLevel(terrainPatchMetric(first, opposite, patchErrors[patchIndex]));
    inner = terrainInnerLevels(outer, own);
}

void main() {
    uint patchIndex = inPatch;
    uint record = uint(gl_VertexIndex);
    vec4 outer;
    vec2 inner;
    if (tess.mode.x == TS_TERRAIN_MODE_CONTINUOUS) {
        // One level for the whole draw, already clamped to 1..14.99.
        outer = vec4(tess.levels.z);
        inner = vec2(tess.levels.z);
    } else {
        adaptiveLevels(patchIndex, outer, inner);
    }
    outOuter = outer;
    outInner = vec4(inner, float(patchIndex), 0.0);
    for (uint piece = 0u; piece < TS_EMU_PIECES; ++piece) outCommands[piece] = tsEmuCommand(outer, inner, piece, record);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
