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

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = TS_BINDING_EDGE_ERROR) readonly buffer EdgeErrors {
    float edgeErrors[];
};
layout(std430, set = 0, binding = TS_BINDING_PATCH_ERROR) readonly buffer PatchErrors {
    float patchErrors[];
};

// The displaced surface at a control-mesh grid point.
vec3 surfacePoint(vec2 grid) {
    vec2 xz = grid * terrain.tiling.zw;
    return vec3(xz.x, terrainHeight(xz), xz.y);
}

float clampLevel(float level) {
    return clamp(level, tess.levels.x, tess.levels.y);
}

float edgeLevel(uint edge) {
    vec2 along;
    vec2 start = tsEdgeStart(edge, tess.mode.z, along);
    vec3 a = surfacePoint(start);
    vec3 b = surfacePoint(start + along);
    vec3 eye = frame.cameraPosition.xyz;
    float ppm = tess.metric.z;
    float target = tess.metric.x;
    uint metric = tess.mode.y;
    if (metric == TS_METRIC_DISTANCE) return tsDistanceLevel(a, b, eye, tess.metric.y, tess.levels.x, tess.levels.y);
    if (metric == TS_METRIC_SILHOUETTE) {
        vec3 na = terrainNormal(a.xz);
        vec3 nb = terrainNormal(b.xz);
        return tsSilhouetteLevel(a, b, na, nb, eye, ppm, target);
    }
    if (metric == TS_METRIC_DETAIL) return tsDetailLevel(a, b, eye, edgeErrors[edge], ppm, target);
    return tsScreenEdgeLevel(a, b, eye, ppm, target);
}

float patchLevel(uint patchIndex) {
    if (tess.mode.y != TS_METRIC_DETAIL) return tess.levels.x;
    uint patches = tess.mode.z;
    vec2 corner = vec2(float(patchIndex % patches), float(patchIndex / patches));
    vec3 c0 = surfacePoint(corner);
    vec3 c1 = surfacePoint(corner + vec2(1.0));
    return tsDetailLevel(c0, c1, frame.cameraPosition.xyz, patchErrors[patchIndex], tess.metric.z, tess.metric.x);
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    uint edges = tess.mode.w;
    uint patchCount = tess.mode.z * tess.mode.z;
    if (id < edges) {
        edgeLevels[id] = clampLevel(edgeLevel(id));
    } else if (id < edges + patchCount) {
        patchLevels[id - edges] = clampLevel(patchLevel(id - edges));
    }
}
