#version 450
// The crowd's impostor tier's cards (crowd_impostor.vert, meshshader's
// mesh stage): the baked base colour and coverage of the two phases around
// the instance's, blended; coverage below one half is not the creature; the
// LOD cross-fade's dither as every tier keeps it (lod_fade.glsl); the baked
// model-space normal turned by the heading; then the same light as the
// meshes (tsLightCharacter: sun, sky, the cascaded shadow maps' receivers,
// fog), the instance's tint and the --lod-colors tint. Depth is the card's
// plane: writing gl_FragDepth would cost early depth testing, and a far
// creature's depth differs from its card's by under its radius.
// TS_CROWD_TEXELS: the emulated backends' crowd bindings (declared only).
// TS_IMPOSTOR_NEAREST_PHASE (CPU devices, crowdImpostorFragment): the
// nearer of the two phases instead of their blend, two samples instead of
// four: on lavapipe each sample is about a sixth of the tier's time, and at
// its 8 to 15 frames a second the frames step between phases anyway (8 to
// a 1.1 s walk cycle: a phase lasts 1 to 2 frames there).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#include "character_shading.glsl"
#include "crowd_impostor.glsl"
#include "lod_fade.glsl"
#include "output_color.glsl"

layout(set = 0, binding = TS_BINDING_CROWD_IMPOSTOR_ALBEDO) uniform sampler2DArray uImpostorAlbedo;
layout(set = 0, binding = TS_BINDING_CROWD_IMPOSTOR_NORMAL) uniform sampler2DArray uImpostorNormal;

layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec2 inUv;
layout(location = 2) flat in uvec4 inCard;      // tsCrowdImpostorFragmentCard()
layout(location = 3) flat in vec4 inCrowdLod;   // tsCrowdFragmentLod()
layout(location = 4) flat in vec4 inCrowdShade; // tsCrowdFragmentShade()
layout(location = 0) out vec4 outColor;

void main() {
    tsCrowdFragmentSelect(inCrowdLod, inCrowdShade);
    float weight = uintBitsToFloat(inCard.z);
    // Every sample before any discard: their mip levels come from the
    // quad's derivatives.
#ifdef TS_IMPOSTOR_NEAREST_PHASE
    const vec3 at = vec3(inUv, float(weight < 0.5 ? inCard.x : inCard.y));
    vec4 albedo = texture(uImpostorAlbedo, at);
    vec3 stored = texture(uImpostorNormal, at).xyz;
#else
    vec4 albedo = mix(texture(uImpostorAlbedo, vec3(inUv, float(inCard.x))),
                      texture(uImpostorAlbedo, vec3(inUv, float(inCard.y))), weight);
    vec3 stored = mix(texture(uImpostorNormal, vec3(inUv, float(inCard.x))).xyz,
                      texture(uImpostorNormal, vec3(inUv, float(inCard.y))).xyz, weight);
#endif
    // The silhouette (coverage) and this draw's share of a cross-fade.
    if (albedo.a < 0.5 || !tsLodKeepPixel(gl_FragCoord.xy, uCharacter.lod.x, uCharacter.lod.y > 0.5)) discard;
    vec3 n = stored * 2.0 - 1.0;
    n = dot(n, n) > 1e-8 ? normalize(tsCrowdImpostorToWorld(n, uintBitsToFloat(inCard.w))) : vec3(0.0, 1.0, 0.0);
    // The image decoded the sRGB bytes (and filtered in linear space); the
    // plain look lights the bytes as they are (tsCharacterAlbedo).
    vec3 base = tsFullLook() ? albedo.rgb : tsLinearToSrgb(albedo.rgb);
    vec3 color = tsLightCharacter(inWorld, n, n, base) * gCrowdTint;
    if (uCharacter.lod.w > 0.5) color *= tsLodTierTint(uint(uCharacter.lod.z));
    outColor = tsOutputColor(color);
}
