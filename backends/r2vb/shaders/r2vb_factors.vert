#version 450
// Pass r2vb.factors (the first paper's pass 2, Listing 15): one point per
// edge of each visible patch, four per patch. Point k fetches its ring's
// corners k and k + 1 from the cage target by vertex texture fetch, which is
// the patch's edge (k + 1) mod 4 in Vulkan quad outer order, and writes that
// edge's level into the factor target. The two ends are swapped so the lower
// grid vertex ID comes first (the paper's vertex-ID swap): both patches that
// share an edge evaluate the metric on the same inputs in the same order, get
// bit-identical levels, and the surface has no cracks.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#define TS_NO_LEVEL_BUFFERS
#include "terrain_tess.glsl"
#include "terrain_metric.glsl"
#include "tessera/shaders/TessPattern.h"
#include "r2vb_points.glsl"

layout(set = 0, binding = R2VB_BINDING_CAGE) uniform sampler2D cage;
layout(std430, set = 0, binding = TS_BINDING_EDGE_ERROR) readonly buffer EdgeErrors {
    float edgeErrors[];
};

layout(location = 0) in uint inPatch; // visible patch index (per instance)

layout(location = 0) flat out float outLevel;

void main() {
    uint k = uint(gl_VertexIndex);
    uint first = uint(gl_InstanceIndex) * 4u;
    uint edge = (k + 1u) & 3u;
    float level;
    if (tess.mode.x == TS_TERRAIN_MODE_CONTINUOUS) {
        level = tess.levels.z; // already clamped to [1, TS_EMU_MAX_LEVEL]
    } else {
        vec4 a = texelFetch(cage, r2vbTexel(first + k, R2VB_CAGE_WIDTH), 0);
        vec4 b = texelFetch(cage, r2vbTexel(first + edge, R2VB_CAGE_WIDTH), 0);
        if (a.w > b.w) {
            vec4 t = a;
            a = b;
            b = t;
        }
        uint patches = tess.mode.z;
        uint canonical = tsPatchEdge(inPatch % patches, inPatch / patches, edge, patches);
        level = terrainClampLevel(terrainEdgeMetric(a.xyz, b.xyz, edgeErrors[canonical]));
    }
    outLevel = level;
    gl_Position = r2vbTexelPosition(first + edge);
    gl_PointSize = 1.0;
}
