// terrain_shading.glsl: materials from the height field alone (no normal map,
// no material textures), after the first paper's Listing 18: rock on slopes,
// grass low and flat, snow on high flat ground with a procedural edge.
//
// Two looks (FrameUniforms::look, docs/LOOKS.md). Plain is the shading from
// before the looks. Full shades in linear light: the same material blend with
// tileable detail textures (triplanar rock on steep slopes, faded to their
// averages with distance), the sun masked by the sun-visibility (horizon) map
// for soft self-shadowing, sky light from the hemisphere, and the
// aerial-perspective fog.
#ifndef TERRAIN_SHADING_GLSL
#define TERRAIN_SHADING_GLSL
#include "common_frame.glsl"
#include "tessera/shaders/CharacterShadow.h"
#include "common_noise.glsl"
#include "sky_atmosphere.glsl"
#include "shadow_receiver.glsl"

// What fraction of the sun each terrain texel sees, made by terrain_sun.frag
// from the height map; sampled bilinearly, which softens the shadow's edge.
layout(set = 0, binding = TS_BINDING_SUN_VISIBILITY) uniform sampler2D sunVisibilityMap;

struct TerrainMaterial {
    vec3 grass, dirt, rock, snow;
};

vec3 terrainAlbedoFrom(TerrainMaterial m, vec3 worldPos, vec3 normal, float detail) {
    float slope = 1.0 - normal.y;                 // 0 flat .. 1 vertical
    float heightFraction = worldPos.y / max(terrain.worldSize.z, 1.0);
    vec3 base = mix(m.grass, m.dirt, smoothstep(0.45, 0.8, detail + heightFraction * 0.6));
    base = mix(base, m.rock, smoothstep(0.18, 0.32, slope + (detail - 0.5) * 0.08));
    // Snow settles where it is high and flat enough to stay, with a noisy line.
    float snowLine = 0.62 + (detail - 0.5) * 0.12;
    float snowAmount = smoothstep(snowLine, snowLine + 0.06, heightFraction) * (1.0 - smoothstep(0.25, 0.45, slope));
    return mix(base, m.snow, snowAmount);
}

float terrainDetail(vec3 worldPos) {
    return valueNoise(worldPos.xz * 0.05) * 0.6 + valueNoise(worldPos.xz * 0.23) * 0.4;
}

vec3 terrainAlbedo(vec3 worldPos, vec3 normal) {
    const TerrainMaterial plain = TerrainMaterial(vec3(0.23, 0.33, 0.12), vec3(0.36, 0.30, 0.22),
                                                  vec3(0.42, 0.39, 0.36), vec3(0.92, 0.94, 0.97));
    return terrainAlbedoFrom(plain, worldPos, normal, terrainDetail(worldPos));
}

vec3 shadeTerrainPlain(vec3 worldPos, vec3 normal) {
    vec3 albedo = terrainAlbedo(worldPos, normal);
    vec3 sun = normalize(frame.sunDirection.xyz);
    float diffuse = max(dot(normal, sun), 0.0);
    float sky = 0.5 + 0.5 * normal.y;
    vec3 color = albedo * (diffuse * vec3(1.0, 0.96, 0.88) * 1.1 + sky * vec3(0.30, 0.36, 0.45));
    float dist = length(worldPos - frame.cameraPosition.xyz);
    float fog = 1.0 - exp(-dist * frame.fogColor.a);
    return mix(color, frame.fogColor.rgb, clamp(fog, 0.0, 1.0));
}

// The detail albedo textures (tessera-texgen's, an sRGB array: the sampler
// returns linear values), one layer per material (TS_DETAIL_*).
layout(set = 0, binding = TS_BINDING_DETAIL) uniform sampler2DArray detailMaps;

// Metres one repeat of a detail texture covers.
const float kDetailTileMetres = 24.0;
// The textures fade into their average colours between these distances: past
// them a texel is smaller than a pixel, mips average it anyway, and skipping
// the samples keeps distant pixels cheap on lavapipe.
const float kDetailFadeStart = 250.0;
const float kDetailFadeEnd = 700.0;
// A material weighing less than this in a pixel is not sampled.
const float kDetailMinWeight = 0.02;

// The mip trilinear filtering would pick for a pixel covering `footprint`
// metres of ground along its longer axis, worked out from the distance and
// the slope rather than from derivatives: the compute resolve has none, and
// forward and deferred shading then filter alike.
float terrainDetailLod(float footprint) {
    float texelMetres = kDetailTileMetres / float(textureSize(detailMaps, 0).x);
    return log2(max(footprint / texelMetres, 1.0));
}

vec3 terrainDetailLayer(vec2 uv, int layer, float lod) {
    return textureLod(detailMaps, vec3(uv, float(layer)), lod).rgb;
}

// Rock seen triplanar: on a cliff the top-down projection would stretch
// into streaks, so each of the three projections weighs by how squarely the
// surface faces its axis (sharpened), and faint ones are skipped.
vec3 terrainDetailRock(vec3 worldPos, vec3 n, float lod) {
    vec3 w = n * n;
    w *= w;
    w /= (w.x + w.y + w.z);
    vec3 p = worldPos / kDetailTileMetres;
    vec3 sum = vec3(0.0);
    float used = 0.0;
    if (w.y > kDetailMinWeight) { sum += w.y * terrainDetailLayer(p.xz, TS_DETAIL_ROCK, lod); used += w.y; }
    if (w.x > kDetailMinWeight) { sum += w.x * terrainDetailLayer(p.zy, TS_DETAIL_ROCK, lod); used += w.x; }
    if (w.z > kDetailMinWeight) { sum += w.z * terrainDetailLayer(p.xy, TS_DETAIL_ROCK, lod); used += w.z; }
    return sum / max(used, 1e-4);
}

// The full look's albedo (linear): the plain look's blend of the same four
// materials by slope, height and noise, each material from its detail
// texture near the camera and its average colour far away. `dist` is the
// distance from the camera, `footprint` the ground a pixel covers (metres).
vec3 terrainAlbedoFull(vec3 worldPos, vec3 normal, float dist, float footprint) {
    float detail = terrainDetail(worldPos);
    float slope = 1.0 - normal.y;
    float heightFraction = worldPos.y / max(terrain.worldSize.z, 1.0);
    float toDirt = smoothstep(0.45, 0.8, detail + heightFraction * 0.6);
    float toRock = smoothstep(0.18, 0.32, slope + (detail - 0.5) * 0.08);
    float snowLine = 0.62 + (detail - 0.5) * 0.12;
    float toSnow = smoothstep(snowLine, snowLine + 0.06, heightFraction) * (1.0 - smoothstep(0.25, 0.45, slope));

    vec3 grass = terrain.detailAverage[TS_DETAIL_GRASS].rgb;
    vec3 dirt = terrain.detailAverage[TS_DETAIL_DIRT].rgb;
    vec3 rock = terrain.detailAverage[TS_DETAIL_ROCK].rgb;
    vec3 snow = terrain.detailAverage[TS_DETAIL_SNOW].rgb;
    float fade = smoothstep(kDetailFadeStart, kDetailFadeEnd, dist);
    if (fade < 1.0) {
        vec2 uv = worldPos.xz / kDetailTileMetres;
        float lod = terrainDetailLod(footprint);
        float ground = (1.0 - toRock) * (1.0 - toSnow);
        if ((1.0 - toDirt) * ground > kDetailMinWeight)
            grass = mix(terrainDetailLayer(uv, TS_DETAIL_GRASS, lod), grass, fade);
        if (toDirt * ground > kDetailMinWeight) dirt = mix(terrainDetailLayer(uv, TS_DETAIL_DIRT, lod), dirt, fade);
        if (toRock * (1.0 - toSnow) > kDetailMinWeight) rock = mix(terrainDetailRock(worldPos, normal, lod), rock, fade);
        if (toSnow > kDetailMinWeight) snow = mix(terrainDetailLayer(uv, TS_DETAIL_SNOW, lod), snow, fade);
    }
    vec3 albedo = mix(mix(mix(grass, dirt, toDirt), rock, toRock), snow, toSnow);
    // The blend's own noise also varies the brightness at the kilometre
    // scale, where the textures have faded: no extra noise evaluations.
    return albedo * (0.8 + 0.4 * detail);
}

layout(set = 0, binding = TS_BINDING_CHARACTER_SHADOW) uniform sampler2D characterShadowMask;

// Sunlight the characters leave on the ground (CharacterShadow.h): the mask
// covers a square ahead of the camera; its last 10% fades out so the edge of
// the square never shows as a line.
float terrainCharacterLight(vec3 worldPos) {
    if (frame.characterShadow.w < 0.5) return 1.0;
    vec2 uv = (worldPos.xz - frame.characterShadow.xy) * frame.characterShadow.z;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    vec2 edge = min(uv, 1.0 - uv);
    float fade = smoothstep(0.0, 0.1, min(edge.x, edge.y));
    return 1.0 - TS_CHARACTER_SHADOW_STRENGTH * fade * textureLod(characterShadowMask, uv, 0.0).r;
}

// The sun the terrain's own relief (the sun-visibility map) and the
// characters (blobs or cascaded shadow maps, whichever the frame draws) leave.
float terrainSunVisibility(vec3 worldPos, vec3 normal) {
    return textureLod(sunVisibilityMap, terrainTexcoord(worldPos.xz), 0.0).r * terrainCharacterLight(worldPos) *
           tsCascadedSunlight(worldPos, normal);
}

// The full look. Runs in the resolve pass (terrain_resolve.glsl) for the
// frame's terrain and forward only for a second terrain in the same frame,
// so it uses no derivatives.
vec3 shadeTerrainFull(vec3 worldPos, vec3 normal) {
    vec3 toPoint = worldPos - frame.cameraPosition.xyz;
    float dist = length(toPoint);
    // A pixel's footprint grows with distance and stretches as the ground
    // turns away from the view (trilinear filtering follows the longer axis).
    float facing = abs(dot(normal, toPoint)) / max(dist, 1e-4);
    float footprint = dist * frame.terrainResolve.y / max(facing, 0.05);
    vec3 albedo = terrainAlbedoFull(worldPos, normal, dist, footprint);
    vec3 sun = tsSunDirection();
    float diffuse = max(dot(normal, sun), 0.0) * terrainSunVisibility(worldPos, normal);
    vec3 color = albedo * (frame.sunColor.rgb * diffuse + tsSkyAmbient(normal));
    return tsApplyFog(color, worldPos);
}

vec3 shadeTerrain(vec3 worldPos, vec3 normal) {
    return tsFullLook() ? shadeTerrainFull(worldPos, normal) : shadeTerrainPlain(worldPos, normal);
}

#endif
