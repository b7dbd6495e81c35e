// terrain_shading.glsl: materials from the height field alone (no normal map,
// no material textures), after the first paper's Listing 18: rock on slopes,
// grass low and flat, snow on high flat ground with a procedural edge.
//
// Two looks (FrameUniforms::look, docs/LOOKS.md). Plain is the shading from
// before the looks, kept bit for bit. Full shades in linear light: the same
// material blend from linear albedos with more macro variation, the sun
// masked by the sun-visibility (horizon) map for soft self-shadowing, sky
// light from the hemisphere, and the aerial-perspective fog.
#ifndef TERRAIN_SHADING_GLSL
#define TERRAIN_SHADING_GLSL
#include "common_frame.glsl"
#include "common_noise.glsl"
#include "sky_atmosphere.glsl"

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

// Linear albedos (measured-looking reflectances, not the plain look's
// display values): dry grass, loam, granite, old snow.
vec3 terrainAlbedoFull(vec3 worldPos, vec3 normal) {
    const TerrainMaterial full = TerrainMaterial(vec3(0.038, 0.082, 0.014), vec3(0.080, 0.064, 0.032),
                                                 vec3(0.150, 0.135, 0.120), vec3(0.80, 0.83, 0.88));
    float detail = terrainDetail(worldPos);
    vec3 albedo = terrainAlbedoFrom(full, worldPos, normal, detail);
    // Macro variation a kilometre across breaks the repetition of the blend.
    float macro = valueNoise(worldPos.xz * 0.0021);
    albedo *= 0.78 + 0.44 * macro;
    // Fine speckle, faded out with distance before it can shimmer.
    float dist = length(worldPos - frame.cameraPosition.xyz);
    float speckle = valueNoise(worldPos.xz * 1.7) - 0.5;
    albedo *= 1.0 + speckle * 0.35 * (1.0 - smoothstep(60.0, 400.0, dist));
    return albedo;
}

float terrainSunVisibility(vec3 worldPos) {
    return texture(sunVisibilityMap, terrainTexcoord(worldPos.xz)).r;
}

vec3 shadeTerrainFull(vec3 worldPos, vec3 normal) {
    vec3 albedo = terrainAlbedoFull(worldPos, normal);
    vec3 sun = tsSunDirection();
    float diffuse = max(dot(normal, sun), 0.0) * terrainSunVisibility(worldPos);
    vec3 color = albedo * (frame.sunColor.rgb * diffuse + tsSkyAmbient(normal));
    return tsApplyFog(color, worldPos);
}

vec3 shadeTerrain(vec3 worldPos, vec3 normal) {
    return tsFullLook() ? shadeTerrainFull(worldPos, normal) : shadeTerrainPlain(worldPos, normal);
}

#endif
