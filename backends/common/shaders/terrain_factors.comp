#version 450
// The factor pre-pass of adaptive tessellation: one invocation per canonical
// edge of the control mesh, then one per patch (its interior detail term).
// Each shared edge is evaluated once, from its endpoints in canonical order,
// and stored; both patches read the stored value, so their factors are
// bit-identical and the surface has no cracks. terrain::computeTessLevels is
// the CPU reference of this shader.
#extension GL_GOOGLE_include_directive : require
#define TS_LEVELS_WRITE
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#include "terrain_tess.glsl"
#include "terrain_metric.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = TS_BINDING_EDGE_ERROR) readonly buffer EdgeErrors {
    float edgeErrors[];
};
layout(std430, set = 0, binding = TS_BINDING_PATCH_ERROR) readonly buffer PatchErrors {
    float patchErrors[];
};

float edgeLevel(uint edge) {
    vec2 along;
    vec2 start = tsEdgeStart(edge, tess.mode.z, along);
    return terrainEdgeMetric(terrainSurfacePoint(start), terrainSurfacePoint(start + along), edgeErrors[edge]);
}

float patchLevel(uint patchIndex) {
    uint patches = tess.mode.z;
    vec2 corner = vec2(float(patchIndex % patches), float(patchIndex / patches));
    return terrainPatchMetric(terrainSurfacePoint(corner), terrainSurfacePoint(corner + vec2(1.0)),
                              patchErrors[patchIndex]);
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    uint edges = tess.mode.w;
    uint patchCount = tess.mode.z * tess.mode.z;
    if (id < edges) {
        edgeLevels[id] = terrainClampLevel(edgeLevel(id));
    } else if (id < edges + patchCount) {
        patchLevels[id - edges] = terrainClampLevel(patchLevel(id - edges));
    }
}
