// character_shading.glsl: lighting of the displaced character from its
// tangent-space normal map, baked by the same tool and in the same tangent
// frame as the displacement (the paper's "Lighting with Tessellation and
// Displacement Mapping"): the map holds the sculpt's normal in the frame of
// the interpolated cage normal and tangent, so it is also the normal of the
// displaced surface.
#ifndef CHARACTER_SHADING_GLSL
#define CHARACTER_SHADING_GLSL
#include "common_frame.glsl"
#include "character_common.glsl"
#include "sky_atmosphere.glsl"
#include "shadow_receiver.glsl"

layout(set = 0, binding = TS_BINDING_BASE_COLOR) uniform sampler2D uBaseColor;
layout(set = 0, binding = TS_BINDING_NORMAL_MAP) uniform sampler2D uNormalMap;

// The base colour tsLightCharacter takes, from one stored sRGB-encoded
// (glTF's rule): linear in the full look, which lights in linear space; in
// the plain look the bytes as they are. Decoded here rather than by an
// _SRGB image format so the plain look still reads the bytes as it always
// did.
vec3 tsCharacterAlbedo(vec3 stored) {
    return tsFullLook() ? tsSrgbToLinear(stored) : stored;
}

// The light a character's surface point at `world` sends to the eye, from
// its shading normal `n` and base colour `albedo` (tsCharacterAlbedo's):
// the sun and the sky (full look, with the other characters' shadows from
// the cascaded shadow maps, offset along `surfaceNormal`, the surface's own
// normal rather than the map's) or the plain look's hemisphere, then fog.
// Every tier of a crowd is lit here, the impostor cards too
// (crowd_impostor.frag), so a tier change changes the shape, not the light.
vec3 tsLightCharacter(vec3 world, vec3 n, vec3 surfaceNormal, vec3 albedo) {
    vec3 sun = normalize(frame.sunDirection.xyz);
    float diffuse = max(dot(n, sun), 0.0);
    if (tsFullLook()) {
        diffuse *= tsCascadedSunlight(world, surfaceNormal);
        vec3 lit = albedo * (frame.sunColor.rgb * diffuse + tsSkyAmbient(n));
        return tsApplyFog(lit, world);
    }
    // Sky above, bounce from the ground below: characters read as lit from
    // every side without a shadow pass.
    float hemi = 0.5 + 0.5 * n.y;
    vec3 ambient = mix(vec3(0.20, 0.18, 0.15), vec3(0.38, 0.45, 0.55), hemi);
    vec3 color = albedo * (ambient + vec3(1.0, 0.95, 0.85) * diffuse);
    return tsApplyFog(color, world);
}

vec3 tsShadeCharacter(vec3 world, vec3 normal, vec3 tangent, vec2 uv) {
    vec3 n = normalize(normal);
    if (uCharacter.displacement.w > 0.5) {
        // Gram-Schmidt: the interpolated tangent is not exactly orthogonal.
        vec3 t = tangent - n * dot(n, tangent);
        t = dot(t, t) > 1e-12 ? normalize(t) : vec3(0.0);
        float handedness = uCharacter.counts.w != 0u ? -1.0 : 1.0;
        vec3 b = handedness * cross(n, t);
        vec3 m = texture(uNormalMap, uv).xyz * 2.0 - 1.0;
        if (dot(t, t) > 0.0) n = normalize(t * m.x + b * m.y + n * m.z);
    }
    return tsLightCharacter(world, n, normalize(normal), tsCharacterAlbedo(texture(uBaseColor, uv).rgb));
}

#endif
