#version 450
// Character shading shared by every backend (character_shading.glsl), with
// the LOD cross-fade's dither and the --lod-colors tint (lod_fade.glsl).
// TS_CROWD: an instanced crowd draw; what shading needs of the instance
// (its fade, tier and tint) comes flat from the vertex or evaluation stage.
#extension GL_GOOGLE_include_directive : require
#include "character_shading.glsl"
#include "lod_fade.glsl"
#include "output_color.glsl"

layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec2 inUv;
layout(location = 0) out vec4 outColor;
#ifdef TS_CROWD
layout(location = 4) flat in vec4 inCrowdLod;   // tsCrowdFragmentLod()
layout(location = 5) flat in vec4 inCrowdShade; // tsCrowdFragmentShade()
#endif

void main() {
#ifdef TS_CROWD
    tsCrowdFragmentSelect(inCrowdLod, inCrowdShade);
#endif
    if (!tsLodKeepPixel(gl_FragCoord.xy, uCharacter.lod.x, uCharacter.lod.y > 0.5)) discard;
    vec3 color = tsShadeCharacter(inWorld, inNormal, inTangent, inUv);
#ifdef TS_CROWD
    color *= gCrowdTint;
#endif
    if (uCharacter.lod.w > 0.5) color *= tsLodTierTint(uint(uCharacter.lod.z));
    outColor = tsOutputColor(color);
}
