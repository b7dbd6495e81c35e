// crowd_common.glsl: what an instanced crowd pass reads (CrowdInstance.h),
// and the bridge that lets the character passes' functions serve a crowd:
// tsCrowdSelect() fills the global uCharacter from a list entry (placement,
// the creature's box and maps, the near level, the fade) and points the
// palette at the instance's baked clip. Included by character_common.glsl
// when TS_CROWD is defined.
#ifndef CROWD_COMMON_GLSL
#define CROWD_COMMON_GLSL
#include "tessera/shaders/CharacterUniforms.h"
#include "tessera/shaders/CrowdInstance.h"
#include "baked_animation.glsl"

#ifndef TS_CROWD_LISTS_ACCESS
#define TS_CROWD_LISTS_ACCESS readonly
#endif

layout(std140, set = 0, binding = TS_BINDING_CROWD) uniform CrowdBlock {
    CrowdUniforms uCrowd;
};
layout(set = 0, binding = TS_BINDING_CROWD_BAKED) uniform samplerBuffer uBakedMatrices;

#ifdef TS_CROWD_TEXELS
// The emulated backends (D3D9 vertex texture fetch, D3D10 Buffer.Load):
// instances and clips as RGBA32UI texel buffers; lists arrive as instance
// vertex streams or near slots, never as storage.
layout(set = 0, binding = TS_BINDING_CROWD_INSTANCES) uniform usamplerBuffer uCrowdInstances;
layout(set = 0, binding = TS_BINDING_CROWD_CLIPS) uniform usamplerBuffer uCrowdClips;

CrowdInstance tsCrowdInstance(uint i) {
    int t = int(i) * 4;
    CrowdInstance instance;
    instance.sphere = uintBitsToFloat(texelFetch(uCrowdInstances, t));
    instance.placement = uintBitsToFloat(texelFetch(uCrowdInstances, t + 1));
    instance.animation = uintBitsToFloat(texelFetch(uCrowdInstances, t + 2));
    instance.ids = texelFetch(uCrowdInstances, t + 3);
    return instance;
}

BakedClip tsCrowdClip(uint i) {
    BakedClip clip;
    clip.frames = texelFetch(uCrowdClips, int(i) * 2);
    clip.timing = uintBitsToFloat(texelFetch(uCrowdClips, int(i) * 2 + 1));
    return clip;
}
#else
layout(std430, set = 0, binding = TS_BINDING_CROWD_INSTANCES) readonly buffer CrowdInstanceBlock {
    CrowdInstance crowdInstances[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_LISTS) TS_CROWD_LISTS_ACCESS buffer CrowdListBlock {
    CrowdListEntry crowdLists[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_CLIPS) readonly buffer CrowdClipBlock {
    BakedClip crowdClips[];
};

CrowdInstance tsCrowdInstance(uint i) {
    return crowdInstances[i];
}

BakedClip tsCrowdClip(uint i) {
    return crowdClips[i];
}
#endif

// A list entry as the stages hand it on (flat uvec4) and back.
uvec4 tsCrowdEntryBits(CrowdListEntry e) {
    return uvec4(e.instance, e.slot, floatBitsToUint(e.coverage), e.flags);
}

CrowdListEntry tsCrowdEntry(uvec4 bits) {
    CrowdListEntry e;
    e.instance = bits.x;
    e.slot = bits.y;
    e.coverage = uintBitsToFloat(bits.z);
    e.flags = bits.w;
    return e;
}

// The instance being drawn, as the character passes read it.
CharacterUniforms uCharacter;
BakedClip gCrowdClip;
float gCrowdPhase;
vec3 gCrowdTint;

mat4 tsPaletteJoint(uint joint) {
    return tsBakedJoint(uBakedMatrices, gCrowdClip, gCrowdPhase, joint);
}

// Makes list entry `entry` the instance the character functions draw, at
// near level `nearLevel` when it is in the near tier.
void tsCrowdSelectAtLevel(CrowdListEntry entry, float nearLevel) {
    CrowdInstance instance = tsCrowdInstance(entry.instance);
    CrowdCharacter c = uCrowd.characters[min(instance.ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
    mat4 world = tsCrowdWorld(instance);
    uCharacter.world = world;
    // A rotation times a uniform scale k: its inverse transpose is itself over k^2.
    float k = max(instance.animation.y, 1e-6);
    uCharacter.worldNormal = world * (1.0 / (k * k));
    uCharacter.boxMin = vec4(c.boxMin.xyz, 0.0);
    uCharacter.boxMax = vec4(c.boxMax.xyz, 0.0);
    uCharacter.uvRange = c.uvRange;
    uint tier = (entry.flags >> 8u) & 255u;
    bool displace = tier == TS_LOD_NEAR && uCrowd.flags.x != 0u;
    float level = tier == TS_LOD_NEAR ? nearLevel : 1.0;
    uCharacter.displacement = vec4(displace ? c.displacement.x : 0.0, displace ? c.displacement.y : 0.0, level,
                                   c.displacement.z);
    uCharacter.counts = uvec4(c.mesh.y, 0u, 0u, c.boxMax.w > 0.5 ? 1u : 0u);
    uCharacter.lod = vec4(entry.coverage, float(entry.flags & 1u), float(tier), float(uCrowd.flags.y));
    gCrowdClip = tsCrowdClip(instance.ids.z);
    gCrowdPhase = instance.animation.x;
    gCrowdTint = unpackUnorm4x8(instance.ids.w).rgb;
}

// The near level of an instance of creature `creature`: its size on screen
// times the creature's levels per pixel, within the frame's cap.
float tsCrowdNearLevel(CrowdInstance instance) {
    CrowdCharacter c = uCrowd.characters[min(instance.ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
    return tsLodLevel(tsLodPixels(instance.sphere, uCrowd.lod), c.boxMin.w, uCrowd.lod);
}

// What a crowd draw's fragment shader needs of its instance, handed on flat
// by the vertex (or evaluation) stage so that fragments read no crowd
// buffer: lod = uCharacter.lod (coverage, fading out, tier, tint by tier);
// shade = (the instance's tint, normal map + 2 * negative handedness).
vec4 tsCrowdFragmentLod() {
    return uCharacter.lod;
}

vec4 tsCrowdFragmentShade() {
    return vec4(gCrowdTint, (uCharacter.displacement.w > 0.5 ? 1.0 : 0.0) + (uCharacter.counts.w != 0u ? 2.0 : 0.0));
}

// The fragment stage's side of the two above.
void tsCrowdFragmentSelect(vec4 lod, vec4 shade) {
    uCharacter.lod = lod;
    uCharacter.displacement.w = mod(shade.w, 2.0);
    uCharacter.counts.w = shade.w >= 2.0 ? 1u : 0u;
    gCrowdTint = shade.rgb;
}

// Makes list entry `entry` the instance drawn, its near level from its size.
void tsCrowdSelect(CrowdListEntry entry) {
    tsCrowdSelectAtLevel(entry, tsCrowdNearLevel(tsCrowdInstance(entry.instance)));
}

#endif
