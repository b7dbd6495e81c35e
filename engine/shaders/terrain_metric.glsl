// terrain_metric.glsl: one canonical control-mesh edge, or one patch, to an
// adaptive tessellation level, for every backend's factor pass (hulldomain's
// compute pre-pass, r2vb's factor render target, streamout's geometry
// shader). Endpoints come in canonical order (increasing X or Z, i.e.
// increasing grid-vertex ID): with the same inputs in the same order, both
// patches of a shared edge get the same level, so there are no cracks.
// terrain::computeTessLevels is the CPU reference.
// Needs common_frame.glsl, terrain_heightmap.glsl and terrain_tess.glsl.
#ifndef TERRAIN_METRIC_GLSL
#define TERRAIN_METRIC_GLSL

// The displaced surface at a control-mesh grid point.
vec3 terrainSurfacePoint(vec2 grid) {
    vec2 xz = grid * terrain.tiling.zw;
    return vec3(xz.x, terrainHeight(xz), xz.y);
}

// The draw's min/max clamp.
float terrainClampLevel(float level) {
    return clamp(level, tess.levels.x, tess.levels.y);
}

// The metric's level for the edge from `a` to `b` (canonical order), before
// clamping. `edgeError` is TerrainDetail's error of that edge (metres).
float terrainEdgeMetric(vec3 a, vec3 b, float edgeError) {
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
    if (metric == TS_METRIC_DETAIL) return tsDetailLevel(a, b, eye, edgeError, ppm, target);
    return tsScreenEdgeLevel(a, b, eye, ppm, target);
}

// The patch's own interior term (detail metric only; the minimum otherwise),
// before clamping. `c0` and `c1` are its first and opposite corners.
float terrainPatchMetric(vec3 c0, vec3 c1, float patchError) {
    if (tess.mode.y != TS_METRIC_DETAIL) return tess.levels.x;
    return tsDetailLevel(c0, c1, frame.cameraPosition.xyz, patchError, tess.metric.z, tess.metric.x);
}

// Inner levels from the clamped outer levels and the patch's own level, as
// every backend's hull stage (real or emulated) sets them: along u the larger
// of the v = 0 and v = 1 edges, along v the larger of the u = 0 and u = 1 edges.
vec2 terrainInnerLevels(vec4 outer, float own) {
    return vec2(max(max(outer.y, outer.w), own), max(max(outer.x, outer.z), own));
}

#endif
