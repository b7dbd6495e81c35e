#version 450
// The terrain's control mesh, untessellated (the paper's low-resolution
// mode): one quad per visible patch, placed by the per-instance patch index
// and displaced by vertex texture fetch.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"

layout(location = 0) in vec2 inLocal; // corner of the patch, {0,1}^2
layout(location = 1) in uint inPatch; // visible patch index (per instance)

layout(location = 0) out vec3 outWorld;

void main() {
    vec2 xz = terrainPatchPoint(inPatch, inLocal);
    vec3 world = vec3(xz.x, terrainHeight(xz), xz.y);
    outWorld = world;
    gl_Position = frame.viewProjection * vec4(world, 1.0);
}
