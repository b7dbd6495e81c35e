#version 450
// Hull (control) stage: per-edge levels come from the factor pre-pass, by
// canonical edge index, so neighbours set identical outer levels on a shared
// edge. Inner levels take the larger of the opposite edges (and the patch's
// own detail term). Continuous mode sets the one level of the draw.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#include "terrain_tess.glsl"
#include "terrain_metric.glsl"

layout(vertices = 1) out;
layout(location = 0) in uint vPatch[];
layout(location = 0) patch out uint tcPatch;

void main() {
    uint patchIndex = vPatch[0];
    tcPatch = patchIndex;
    if (tess.mode.x == TS_TERRAIN_MODE_CONTINUOUS) {
        float level = tess.levels.z;
        gl_TessLevelOuter[0] = level;
        gl_TessLevelOuter[1] = level;
        gl_TessLevelOuter[2] = level;
        gl_TessLevelOuter[3] = level;
        gl_TessLevelInner[0] = level;
        gl_TessLevelInner[1] = level;
        return;
    }
    uint patches = tess.mode.z;
    uint x = patchIndex % patches;
    uint z = patchIndex / patches;
    float outer0 = edgeLevels[tsPatchEdge(x, z, 0u, patches)];
    float outer1 = edgeLevels[tsPatchEdge(x, z, 1u, patches)];
    float outer2 = edgeLevels[tsPatchEdge(x, z, 2u, patches)];
    float outer3 = edgeLevels[tsPatchEdge(x, z, 3u, patches)];
    float own = patchLevels[patchIndex];
    gl_TessLevelOuter[0] = outer0;
    gl_TessLevelOuter[1] = outer1;
    gl_TessLevelOuter[2] = outer2;
    gl_TessLevelOuter[3] = outer3;
    vec2 inner = terrainInnerLevels(vec4(outer0, outer1, outer2, outer3), own);
    gl_TessLevelInner[0] = inner.x;
    gl_TessLevelInner[1] = inner.y;
}
