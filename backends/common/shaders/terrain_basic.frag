#version 450
// Terrain shading from the height map alone: per-pixel central-difference
// normal and slope/height material blend, through the shared output
// transform (tone mapping and sRGB encode in the full look).
#extension GL_GOOGLE_include_directive : require
#include "terrain_heightmap.glsl"
#include "terrain_shading.glsl"
#include "output_color.glsl"

layout(location = 0) in vec3 inWorld;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 n = terrainNormal(inWorld.xz);
    outColor = tsOutputColor(shadeTerrain(inWorld, n));
}
