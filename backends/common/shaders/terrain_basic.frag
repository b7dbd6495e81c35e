#version 450
// Terrain shading from the height map alone: per-pixel central-difference
// normal and slope/height material blend, through the shared output
// transform (tone mapping and sRGB encode in the full look). In the full
// look the frame's terrain is shaded later, once per pixel, by the terrain
// resolve pass (terrain_resolve.glsl).
#extension GL_GOOGLE_include_directive : require
#include "terrain_heightmap.glsl"
#include "terrain_resolve.glsl"

layout(location = 0) in vec3 inWorld;
layout(location = 0) out vec4 outColor;

void main() {
    // Full look: the terrain resolve pass shades this pixel later, from the
    // distance stored here; alpha 0 marks it as not yet shaded.
    if (frame.terrainResolve.x > 0.5) {
        outColor = vec4(tsPackResolveDistance(length(inWorld - frame.cameraPosition.xyz)), 0.0);
        return;
    }
    vec3 n = terrainNormal(inWorld.xz);
    outColor = tsOutputColor(shadeTerrain(inWorld, n));
}
