// terrain_heightmap.glsl: height-field access shared by every terrain stage.
//
// Sample (i, j) of a W x H field lies at world (i * spacing, j * spacing) and at
// texture coordinate ((i + 0.5) / W, (j + 0.5) / H). The normal is the central
// difference of the field, the same formula as HeightField::normalAt on the
// CPU, so gameplay queries and shading agree.
#ifndef TERRAIN_HEIGHTMAP_GLSL
#define TERRAIN_HEIGHTMAP_GLSL
#include "tessera/shaders/TerrainUniforms.h"

layout(std140, set = 0, binding = TS_BINDING_TERRAIN) uniform TerrainBlock {
    TerrainUniforms terrain;
};
layout(set = 0, binding = TS_BINDING_HEIGHTMAP) uniform sampler2D heightMap;

vec2 terrainTexcoord(vec2 worldXZ) {
    return (worldXZ / terrain.worldSize.w + 0.5) * terrain.heightTexel.xy;
}

float terrainHeight(vec2 worldXZ) {
    return textureLod(heightMap, terrainTexcoord(worldXZ), 0.0).r * terrain.worldSize.z;
}

// World XZ of the point at patch-local (u, v) of control-mesh patch `patchIndex`.
// Written as (corner + uv) * size so that a point on an edge shared by two
// patches gets bit-identical coordinates from both (e.g. (x + 1.0) and
// (x + 1 + 0.0) are the same float): with identical tessellation factors that
// is what keeps adaptive tessellation free of cracks.
vec2 terrainPatchPoint(uint patchIndex, vec2 uv) {
    uint patches = uint(terrain.tiling.x);
    precise vec2 corner = vec2(float(patchIndex % patches), float(patchIndex / patches)) + uv;
    precise vec2 xz = corner * terrain.tiling.zw;
    return xz;
}

vec3 terrainNormal(vec2 worldXZ) {
    float s = terrain.worldSize.w;
    float hl = terrainHeight(worldXZ - vec2(s, 0.0));
    float hr = terrainHeight(worldXZ + vec2(s, 0.0));
    float hd = terrainHeight(worldXZ - vec2(0.0, s));
    float hu = terrainHeight(worldXZ + vec2(0.0, s));
    return normalize(vec3(hl - hr, 2.0 * s, hd - hu));
}

#endif
