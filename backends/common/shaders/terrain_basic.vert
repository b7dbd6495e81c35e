#version 450
// The terrain's control mesh, displaced by vertex texture fetch: one grid per
// visible tile, placed by the per-instance tile index.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"

layout(location = 0) in vec2 inLocal; // position inside the tile, [0,1]^2
layout(location = 1) in uint inTile;  // visible tile index (per instance)

layout(location = 0) out vec3 outWorld;

void main() {
    uint tiles = uint(terrain.tiling.x);
    vec2 tile = vec2(inTile % tiles, inTile / tiles);
    vec2 xz = (tile + inLocal) * terrain.tiling.z;
    vec3 world = vec3(xz.x, terrainHeight(xz), xz.y);
    outWorld = world;
    gl_Position = frame.viewProjection * vec4(world, 1.0);
}
