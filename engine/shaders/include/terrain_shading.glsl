// terrain_shading.glsl: materials from the height field alone (no normal map,
// no material textures), after the first paper's Listing 18: rock on slopes,
// grass low and flat, snow on high flat ground with a procedural edge.
#ifndef TERRAIN_SHADING_GLSL
#define TERRAIN_SHADING_GLSL
#include "common_frame.glsl"
#include "common_noise.glsl"

vec3 terrainAlbedo(vec3 worldPos, vec3 normal) {
    const vec3 grass = vec3(0.23, 0.33, 0.12);
    const vec3 dirt = vec3(0.36, 0.30, 0.22);
    const vec3 rock = vec3(0.42, 0.39, 0.36);
    const vec3 snow = vec3(0.92, 0.94, 0.97);
    float slope = 1.0 - normal.y;                 // 0 flat .. 1 vertical
    float detail = valueNoise(worldPos.xz * 0.05) * 0.6 + valueNoise(worldPos.xz * 0.23) * 0.4;
    float heightFraction = worldPos.y / max(terrain.worldSize.z, 1.0);
    vec3 base = mix(grass, dirt, smoothstep(0.45, 0.8, detail + heightFraction * 0.6));
    base = mix(base, rock, smoothstep(0.18, 0.32, slope + (detail - 0.5) * 0.08));
    // Snow settles where it is high and flat enough to stay, with a noisy line.
    float snowLine = 0.62 + (detail - 0.5) * 0.12;
    float snowAmount = smoothstep(snowLine, snowLine + 0.06, heightFraction) * (1.0 - smoothstep(0.25, 0.45, slope));
    return mix(base, snow, snowAmount);
}

vec3 shadeTerrain(vec3 worldPos, vec3 normal) {
    vec3 albedo = terrainAlbedo(worldPos, normal);
    vec3 sun = normalize(frame.sunDirection.xyz);
    float diffuse = max(dot(normal, sun), 0.0);
    float sky = 0.5 + 0.5 * normal.y;
    vec3 color = albedo * (diffuse * vec3(1.0, 0.96, 0.88) * 1.1 + sky * vec3(0.30, 0.36, 0.45));
    float dist = length(worldPos - frame.cameraPosition.xyz);
    float fog = 1.0 - exp(-dist * frame.fogColor.a);
    return mix(color, frame.fogColor.rgb, clamp(fog, 0.0, 1.0));
}

#endif
