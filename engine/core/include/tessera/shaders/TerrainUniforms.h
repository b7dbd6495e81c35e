// TerrainUniforms.h: what every terrain pass knows about the height field.
#ifndef TESSERA_TERRAIN_UNIFORMS_H
#define TESSERA_TERRAIN_UNIFORMS_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

struct TerrainUniforms {
    vec4 worldSize;   // x: extent along X (m), y: extent along Z (m), z: height scale (m at 1.0), w: sample spacing (m)
    vec4 heightTexel; // x: 1/width, y: 1/height, z: width, w: height (samples)
    vec4 tiling;      // x: patches per side, y: unused, z: patch size along X (m), w: patch size along Z (m)
    // Each detail layer's average albedo (linear rgb, TS_DETAIL_*), which
    // distant terrain uses instead of sampling the textures.
    vec4 detailAverage[4];
};
TS_CHECK_SIZE(TerrainUniforms, 112)

// Push constants of the sun-visibility pass (terrain_sun.frag), which marches
// the height map towards the sun from every texel of the visibility map.
struct TerrainSunParams {
    vec4 sun;   // xyz: unit vector towards the sun, w: penumbra half-width (radians)
    vec4 march; // x: steps, y: first step (m), z: growth per step, w: height bias (m)
    vec4 map;   // xy: 1 / the visibility map's size (texels), zw: unused
};
TS_CHECK_SIZE(TerrainSunParams, 48)

TS_NAMESPACE_END

#define TS_BINDING_TERRAIN 1
#define TS_BINDING_HEIGHTMAP 2
// The sun-visibility (horizon) map the terrain's fragment shading samples
// (terrain_shading.glsl); numbered past the tessellation (3..9) and crowd
// (10..22) bindings so every terrain layout can declare it.
#define TS_BINDING_SUN_VISIBILITY 24
// The detail albedo texture array (sRGB, mipmapped, repeating) and its layers.
#define TS_BINDING_DETAIL 25
#define TS_DETAIL_GRASS 0
#define TS_DETAIL_DIRT 1
#define TS_DETAIL_ROCK 2
#define TS_DETAIL_SNOW 3
// The characters' shadow mask (CharacterShadow.h), R8 darkness over the
// square of ground FrameUniforms::characterShadow places.
#define TS_BINDING_CHARACTER_SHADOW 26
// The terrain resolve pass (terrain_resolve.glsl): what the main pass left
// in the target, as a copy to sample (fragment resolve) or the target itself
// as a storage image (compute resolve).
#define TS_BINDING_RESOLVE_SOURCE 27
#define TS_BINDING_RESOLVE_TARGET 28
// The terrain's main-pass fragments store their distance from the camera in
// the target's RGB as 24-bit fixed point over this range (metres): 4 mm steps.
#define TS_RESOLVE_MAX_DISTANCE 65536.0
#define TS_DETAIL_LAYERS 4

#endif
