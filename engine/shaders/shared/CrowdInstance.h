// CrowdInstance.h: what an instanced crowd draw reads, host and GLSL alike.
//
// The host uploads one CrowdInstance per agent each frame and a
// CrowdUniforms block (the LOD manager's parameters and a record per
// creature). A backend's culling and binning pass runs tsLodUpdate
// (CrowdLod.h) per instance against its LOD state buffer and appends the
// survivors to one list per (tier, creature) as CrowdListEntry; the tier
// draws are instanced over those lists, skinned on the GPU from the baked
// clips (BakedAnimation.h). Nothing per agent is built on the CPU but the
// instance itself.
//
// Bindings of the crowd passes (set 0), after the frame's:
//   TS_BINDING_CROWD (10)            CrowdUniforms
//   TS_BINDING_CROWD_INSTANCES (11)  CrowdInstance[]
//   TS_BINDING_CROWD_LISTS (12)      CrowdListEntry[] (every list's region)
//   TS_BINDING_CROWD_BAKED (13)      the baked joint matrices (RGBA32F texel buffer)
//   TS_BINDING_CROWD_CLIPS (14)      BakedClip[]
//   TS_BINDING_CROWD_VERTICES (15)   CharacterVertex[] of every creature (cages, then far meshes)
//   TS_BINDING_CROWD_STATE (16)      uint LOD state per instance id
//   TS_BINDING_CROWD_ARGS (17)       the indirect commands and counters
//   TS_BINDING_CROWD_NEAR (18)       uvec4 compressed cages of the near slots
//   TS_BINDING_CROWD_SLOTS (19)      uvec2 (instance, creature) per near slot
#ifndef TESSERA_CROWD_INSTANCE_H
#define TESSERA_CROWD_INSTANCE_H
#include "CrowdLod.h"
#include "SharedTypes.h"

/// Creatures one crowd may mix (one list per tier and creature).
#define TS_CROWD_MAX_CHARACTERS 8u
/// Lists: tier-major, (tier * TS_CROWD_MAX_CHARACTERS + creature).
#define TS_CROWD_LISTS (TS_LOD_TIERS * TS_CROWD_MAX_CHARACTERS)

TS_NAMESPACE_BEGIN

/// One agent (64 bytes).
struct CrowdInstance {
    vec4 sphere;    // xyz: bounding-sphere centre (world), w: radius: what culling and the LOD read
    vec4 placement; // xyz: feet position (world), w: heading (radians about +Y; 0 faces +Z)
    vec4 animation; // x: clip phase (BakedAnimation.h), y: scale (model to world), zw: 0
    uvec4 ids;      // x: id (the LOD state's key), y: creature, z: global baked clip, w: tint (RGBA8, 255 = none)
};
TS_CHECK_SIZE(CrowdInstance, 64)

/// One creature of the crowd (80 bytes).
struct CrowdCharacter {
    vec4 boxMin;       // xyz: compression box minimum (model space), w: near-tier levels per pixel
    vec4 boxMax;       // xyz: compression box maximum, w: 1 = bitangent is -cross(n, t)
    vec4 uvRange;      // xy: uv minimum, zw: uv maximum
    vec4 displacement; // x: scale, y: bias (0, 0: none), z: 1 = normal map, w: 0
    uvec4 mesh;        // x: first cage vertex, y: cage vertices, z: first far vertex, w: far vertices (in the crowd's vertex buffer)
};
TS_CHECK_SIZE(CrowdCharacter, 80)

struct CrowdUniforms {
    CrowdLodParams lod;
    CrowdCharacter characters[TS_CROWD_MAX_CHARACTERS];
    uvec4 counts; // x: instances, y: creatures, z: near slots, w: list capacity (entries per list)
    uvec4 flags;  // x: 1 = displacement, y: 1 = tint by tier (--lod-colors), z: near slot stride (largest cage vertex count), w: state entries (ids)
};
TS_CHECK_SIZE(CrowdUniforms, 832)

/// One drawn instance in a list (16 bytes).
struct CrowdListEntry {
    uint instance; // index into the frame's CrowdInstance[]
    uint slot;     // near tier: its compressed cage's slot; else 0
    float coverage;
    uint flags;    // bit 0: the fading-out copy; bits 8..15: tier
};
TS_CHECK_SIZE(CrowdListEntry, 16)

/// The region of list (tier, creature) in the lists buffer.
TS_INLINE uint tsCrowdListBase(uint tier, uint creature, uint capacity) {
    return (tier * TS_CROWD_MAX_CHARACTERS + creature) * capacity;
}

/// The world matrix of an instance: translate to its feet, turn by the
/// heading about +Y, scale.
TS_INLINE mat4 tsCrowdWorld(CrowdInstance instance) {
    const float c = cos(instance.placement.w), s = sin(instance.placement.w), k = instance.animation.y;
    return mat4(vec4(c * k, 0.0f, -s * k, 0.0f), vec4(0.0f, k, 0.0f, 0.0f), vec4(s * k, 0.0f, c * k, 0.0f),
                vec4(instance.placement.x, instance.placement.y, instance.placement.z, 1.0f));
}

TS_NAMESPACE_END

#define TS_BINDING_CROWD 10
#define TS_BINDING_CROWD_INSTANCES 11
#define TS_BINDING_CROWD_LISTS 12
#define TS_BINDING_CROWD_BAKED 13
#define TS_BINDING_CROWD_CLIPS 14
#define TS_BINDING_CROWD_VERTICES 15
#define TS_BINDING_CROWD_STATE 16
#define TS_BINDING_CROWD_ARGS 17
#define TS_BINDING_CROWD_NEAR 18
#define TS_BINDING_CROWD_SLOTS 19

/// The indirect buffer (uint words): per list an indexed draw command
/// (5 words: indexCount, instanceCount, firstIndex, vertexOffset,
/// firstInstance), then the near skin dispatch (3 words: x = near slots
/// used, 1, 1), then the near slot counter.
#define TS_CROWD_ARG_DRAW_WORDS 5u
#define TS_CROWD_ARG_DISPATCH (TS_CROWD_LISTS * TS_CROWD_ARG_DRAW_WORDS)
#define TS_CROWD_ARG_WORDS (TS_CROWD_ARG_DISPATCH + 4u)

#endif
