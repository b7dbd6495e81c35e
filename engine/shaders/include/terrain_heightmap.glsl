// terrain_heightmap.glsl: height-field access shared by every terrain stage.
//
// Sample (i, j) of a W x H field lies at world (i * spacing, j * spacing) and at
// texture coordinate ((i + 0.5) / W, (j + 0.5) / H). The normal is the central
// difference of the field, the same formula as HeightField::normalAt on the
// CPU, so gameplay queries and shading agree.
#ifndef TERRAIN_HEIGHTMAP_GLSL
#define TERRAIN_HEIGHTMAP_GLSL
#include "TerrainUniforms.h"

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

vec3 terrainNormal(vec2 worldXZ) {
    float s = terrain.worldSize.w;
    float hl = terrainHeight(worldXZ - vec2(s, 0.0));
    float hr = terrainHeight(worldXZ + vec2(s, 0.0));
    float hd = terrainHeight(worldXZ - vec2(0.0, s));
    float hu = terrainHeight(worldXZ + vec2(0.0, s));
    return normalize(vec3(hl - hr, 2.0 * s, hd - hu));
}

#endif
