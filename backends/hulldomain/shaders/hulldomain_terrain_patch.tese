#version 450
// Domain (evaluation) stage: the point of the patch at the tessellation
// coordinate, displaced by the height map. Fractional odd spacing moves new
// vertices in smoothly as a level grows, so there is no popping.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"

layout(quads, fractional_odd_spacing, ccw) in;
layout(location = 0) patch in uint tcPatch;
layout(location = 0) out vec3 outWorld;

void main() {
    vec2 xz = terrainPatchPoint(tcPatch, gl_TessCoord.xy);
    vec3 world = vec3(xz.x, terrainHeight(xz), xz.y);
    outWorld = world;
    gl_Position = frame.viewProjection * vec4(world, 1.0);
}
