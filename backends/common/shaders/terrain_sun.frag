#version 450
// The terrain's sun-visibility (horizon) map, from the height map alone:
// each texel marches towards the sun over the height field, keeps the
// steepest rise it meets and compares it with the sun's elevation. The
// result is the fraction of the sun's (widened) disc above that horizon, so
// the map is soft where the horizon grazes the sun. A fragment shader into a
// render target, so the D3D9-style backend runs it too.
#extension GL_GOOGLE_include_directive : require
#include "terrain_heightmap.glsl"

layout(push_constant) uniform SunBlock {
    TerrainSunParams params;
};
layout(location = 0) out float outVisibility;

void main() {
    // Texel centre in [0,1]^2 of the map, then world XZ (the inverse of
    // terrainTexcoord, so the terrain samples it where it lies).
    vec2 uv = gl_FragCoord.xy * params.map.xy;
    vec2 worldXZ = (uv / terrain.heightTexel.xy - 0.5) * terrain.worldSize.w;
    float h0 = terrainHeight(worldXZ) + params.march.w;
    vec3 sun = normalize(params.sun.xyz);
    float horizontal = length(sun.xz);
    if (horizontal < 1e-4) {
        outVisibility = 1.0; // the sun overhead: nothing rises above it
        return;
    }
    vec2 dir = sun.xz / horizontal;
    float sunElevation = atan(sun.y, horizontal);
    float maxRise = -1e9; // tangent of the steepest horizon seen so far
    float t = params.march.y;
    int steps = int(params.march.x);
    for (int i = 0; i < steps; ++i) {
        float h = terrainHeight(worldXZ + dir * t);
        maxRise = max(maxRise, (h - h0) / t);
        t *= params.march.z;
    }
    float horizon = atan(maxRise);
    outVisibility = smoothstep(-params.sun.w, params.sun.w, sunElevation - horizon);
}
