// crowd_common.glsl: what an instanced crowd pass reads (CrowdInstance.h),
// and the bridge that lets the character passes' functions serve a crowd:
// tsCrowdSelect() fills the global uCharacter from a list entry (placement,
// the creature's box and maps, the near level, the fade) and points the
// palette at the instance's baked clip. Included by character_common.glsl
// when TS_CROWD is defined.
#ifndef CROWD_COMMON_GLSL
#define CROWD_COMMON_GLSL
#include "CharacterUniforms.h"
#include "CrowdInstance.h"
#include "baked_animation.glsl"

#ifndef TS_CROWD_LISTS_ACCESS
#define TS_CROWD_LISTS_ACCESS readonly
#endif

layout(std140, set = 0, binding = TS_BINDING_CROWD) uniform CrowdBlock {
    CrowdUniforms uCrowd;
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_INSTANCES) readonly buffer CrowdInstanceBlock {
    CrowdInstance crowdInstances[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_LISTS) TS_CROWD_LISTS_ACCESS buffer CrowdListBlock {
    CrowdListEntry crowdLists[];
};
layout(set = 0, binding = TS_BINDING_CROWD_BAKED) uniform samplerBuffer uBakedMatrices;
layout(std430, set = 0, binding = TS_BINDING_CROWD_CLIPS) readonly buffer CrowdClipBlock {
    BakedClip crowdClips[];
};

// The instance being drawn, as the character passes read it.
CharacterUniforms uCharacter;
BakedClip gCrowdClip;
float gCrowdPhase;
vec3 gCrowdTint;

mat4 tsPaletteJoint(uint joint) {
    return tsBakedJoint(uBakedMatrices, gCrowdClip, gCrowdPhase, joint);
}

// Makes list entry `entry` the instance the character functions draw.
void tsCrowdSelect(CrowdListEntry entry) {
    CrowdInstance instance = crowdInstances[entry.instance];
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
    float level = tier == TS_LOD_NEAR ? tsLodLevel(tsLodPixels(instance.sphere, uCrowd.lod), c.boxMin.w, uCrowd.lod)
                                      : 1.0;
    uCharacter.displacement = vec4(displace ? c.displacement.x : 0.0, displace ? c.displacement.y : 0.0, level,
                                   c.displacement.z);
    uCharacter.counts = uvec4(c.mesh.y, 0u, 0u, c.boxMax.w > 0.5 ? 1u : 0u);
    uCharacter.lod = vec4(entry.coverage, float(entry.flags & 1u), float(tier), float(uCrowd.flags.y));
    gCrowdClip = crowdClips[instance.ids.z];
    gCrowdPhase = instance.animation.x;
    gCrowdTint = unpackUnorm4x8(instance.ids.w).rgb;
}

#endif
