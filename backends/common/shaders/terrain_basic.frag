#version 450
// Terrain shading from the height map alone: per-pixel central-difference
// normal and slope/height material blend.
#extension GL_GOOGLE_include_directive : require
#include "terrain_heightmap.glsl"
#include "terrain_shading.glsl"

layout(location = 0) in vec3 inWorld;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 n = terrainNormal(inWorld.xz);
    outColor = vec4(shadeTerrain(inWorld, n), 1.0);
}
