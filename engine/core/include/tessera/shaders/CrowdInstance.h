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
//   TS_BINDING_CROWD_IMPOSTOR_ALBEDO (51), _NORMAL (52)  the impostor tier's atlases
#ifndef TESSERA_CROWD_INSTANCE_H
#define TESSERA_CROWD_INSTANCE_H
#include "tessera/shaders/CrowdImpostor.h"
#include "tessera/shaders/CrowdLod.h"
#include "tessera/shaders/SharedTypes.h"
#include "tessera/shaders/TessTrianglePattern.h"

/// Creatures one crowd may mix (one list per tier and creature).
#define TS_CROWD_MAX_CHARACTERS 8u
/// Lists: tier-major, (tier * TS_CROWD_MAX_CHARACTERS + creature).
#define TS_CROWD_LISTS (TS_LOD_TIERS * TS_CROWD_MAX_CHARACTERS)
/// Words per emulated near-slot command (VkDrawIndexedIndirectCommand's 5,
/// padded to two 16-byte texels so a render target can write it).
#define TS_CROWD_NEAR_COMMAND_WORDS 8u

TS_NAMESPACE_BEGIN

/// One agent (64 bytes).
struct CrowdInstance {
    vec4 sphere;    // xyz: bounding-sphere centre (world), w: radius: what culling and the LOD read
    vec4 placement; // xyz: feet position (world), w: heading (radians about +Y; 0 faces +Z)
    vec4 animation; // x: clip phase (BakedAnimation.h), y: scale (model to world), zw: 0
    uvec4 ids;      // x: id (the LOD state's key), y: creature, z: global baked clip, w: tint (RGBA8, 255 = none)
};
TS_CHECK_SIZE(CrowdInstance, 64)

/// One creature of the crowd (96 bytes).
struct CrowdCharacter {
    vec4 boxMin;       // xyz: compression box minimum (model space), w: near-tier levels per pixel
    vec4 boxMax;       // xyz: compression box maximum, w: 1 = bitangent is -cross(n, t)
    vec4 uvRange;      // xy: uv minimum, zw: uv maximum
    vec4 displacement; // x: scale, y: bias (0, 0: none), z: 1 = normal map, w: 0
    uvec4 mesh;        // x: first cage vertex, y: cage vertices, z: first far vertex, w: far vertices (in the crowd's vertex buffer)
    uvec4 indices;     // x: first cage index, y: cage triangles, z: first far index, w: far triangles (in its index buffer)
};
TS_CHECK_SIZE(CrowdCharacter, 96)

struct CrowdUniforms {
    CrowdLodParams lod;
    CrowdCharacter characters[TS_CROWD_MAX_CHARACTERS];
    uvec4 counts; // x: instances, y: creatures, z: near slots, w: list capacity (entries per list)
    uvec4 flags;  // x: 1 = displacement, y: 1 = tint by tier (--lod-colors), z: near slot stride (largest cage vertex count), w: state entries (ids)
    // The emulated backends' near tier (r2vb, streamout): per pattern class
    // (TessTrianglePattern.h) x = first index, y = index count, z = first
    // point code (vertexOffset) in the crowd's triangle pattern library.
    uvec4 nearPatterns[TS_EMU_TRIANGLE_CLASSES];
    uvec4 emulated; // x: instance stride of a near slot's draw (largest cage triangle count), yzw: 0
    // The impostor cards' covered rectangles (tsImpostorPackBounds), per
    // creature and view cell: word tsCrowdImpostorBoundsWord(creature, cell).
    uvec4 impostorBounds[TS_CROWD_MAX_CHARACTERS * TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_VIEWS / 4u];
    // Per creature, its first instance in the frame's instances (sorted by
    // creature): where its lists start in each tier's region
    // (tsCrowdListBase); word c of the array.
    uvec4 creatureFirst[TS_CROWD_MAX_CHARACTERS / 4u];
};
TS_CHECK_SIZE(CrowdUniforms, 3200)

/// Which word of CrowdUniforms::impostorBounds (as uints) holds creature
/// `creature`'s rectangle in view cell `cell`.
TS_INLINE uint tsCrowdImpostorBoundsWord(uint creature, uvec2 cell) {
    return (creature * TS_IMPOSTOR_VIEWS + cell.y) * TS_IMPOSTOR_VIEWS + cell.x;
}

/// One drawn instance in a list (16 bytes).
struct CrowdListEntry {
    uint instance; // index into the frame's CrowdInstance[]
    uint slot;     // near tier: its compressed cage's slot; else 0
    float coverage;
    uint flags;    // bit 0: the fading-out copy; bits 8..15: tier
};
TS_CHECK_SIZE(CrowdListEntry, 16)

/// One near slot of an emulated backend's near tier (16 bytes): the
/// instance whose compressed cage the slot holds and how it is drawn. The
/// level is stored, not recomputed, so the draw's pattern class and the
/// points it places come from the same number.
struct CrowdNearSlot {
    uint instance; // index into the frame's CrowdInstance[]
    uint flags;    // bit 0: the fading-out copy; bits 8..15: tier (TS_LOD_NEAR); bit 31: slot in use
    float coverage;
    float level;   // the near level (tsLodLevel), at most TS_EMU_MAX_LEVEL
};
TS_CHECK_SIZE(CrowdNearSlot, 16)

/// The list entry a near slot draws (its slot index in `slot`).
TS_INLINE CrowdListEntry tsCrowdNearEntry(CrowdNearSlot s, uint slot) {
    CrowdListEntry e;
    e.instance = s.instance;
    e.slot = slot;
    e.coverage = s.coverage;
    e.flags = s.flags & 0xffffu;
    return e;
}

/// The indexed indirect command (VkDrawIndexedIndirectCommand, padded to
/// TS_CROWD_NEAR_COMMAND_WORDS words) at (creature `creature`, slot `slot`)
/// of an emulated backend's near commands: creature c's draw binds c's maps
/// and runs the commands of every slot, and a slot draws only in its own
/// instance's creature (`slotCreature`). It draws the creature's cage
/// triangles as instances (slot * emulated.x + triangle), each one the
/// pattern of the slot's level. Words: index count, instance count, first
/// index, vertex offset (first point code); the fifth, first instance,
/// comes back in `firstInstance`.
TS_INLINE uvec4 tsCrowdNearCommand(CrowdUniforms u, CrowdNearSlot s, uint slotCreature, uint creature, uint slot,
                                   TS_OUT(uint) firstInstance) {
    firstInstance = slot * u.emulated.x;
    if ((s.flags & 0x80000000u) == 0u || slotCreature != creature || creature >= TS_CROWD_MAX_CHARACTERS)
        return uvec4(0u, 0u, 0u, 0u);
    const uvec4 pattern = u.nearPatterns[tsEmuTriangleClass(tsEmuTriangleLevel(s.level))];
    return uvec4(pattern.y, u.characters[creature].indices.y, pattern.x, pattern.z);
}

/// The first word of command (creature, slot) in the near commands.
TS_INLINE uint tsCrowdNearCommandBase(uint creature, uint slot, uint nearSlots) {
    return (creature * nearSlots + slot) * TS_CROWD_NEAR_COMMAND_WORDS;
}

/// The first entry of list (tier, creature) in the lists buffer: each tier
/// a region of `capacity` entries (the most instances), and in it each
/// creature's list from its first instance in the frame's instances
/// (`creatureFirst`; they are sorted by creature). A creature's list holds
/// at most its instances (an instance is never twice in one tier), so the
/// lists cost a tier's entry per instance, whatever the creatures.
TS_INLINE uint tsCrowdListBase(uint tier, uint creatureFirst, uint capacity) {
    return tier * capacity + creatureFirst;
}

/// The corner index `i` (< TS_CROWD_IMPOSTOR_INDICES) of an impostor card
/// names: corner k is (s, t) = (k & 1, k >> 1) of the card, s to the right
/// and t down (t = 0 the top), and the two triangles (2, 3, 1) and
/// (2, 1, 0) are counter-clockwise seen from the eye the card faces. The
/// crowd's index buffer (GpuCrowd) and meshshader's mesh stage both take
/// the card from here.
TS_INLINE uint tsCrowdImpostorIndex(uint i) {
    return (0x012132u >> (4u * i)) & 15u;
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
/// The crowd's index buffer as an R32UI texel buffer (the emulated near
/// tier fetches a cage triangle's corners by instance).
#define TS_BINDING_CROWD_INDICES 20
/// The middle and far tiers' baked vertex animation (character::
/// appendBakedVertices): RGBA32UI texels, one 128-bit vertex per mesh
/// vertex per baked frame; and per global baked clip one RGBA32UI texel:
/// x = the cage's first texel, y = the far mesh's first texel.
#define TS_BINDING_CROWD_BAKED_VERTICES 21
#define TS_BINDING_CROWD_CLIP_MESHES 22
/// The horizon's grid (CrowdLod.h, tsLodBehindTerrain): one R32F texel per
/// cell, the lowest drawn height over it (crowd_occluders.glsl).
#define TS_BINDING_CROWD_OCCLUDERS 50
/// The most cells a side of the horizon's grid has (GpuCrowd's buffers).
#define TS_CROWD_MAX_OCCLUDER_CELLS 128u
/// The impostor tier's atlases (CrowdImpostor.h), every creature's layers in
/// the order of the crowd's global baked clips, so that an instance's first
/// layer is ids.z * TS_IMPOSTOR_PHASES: base colour and coverage (a
/// 2D-array sampler over R8G8B8A8_SRGB) and the model-space normal
/// (R8G8B8A8_UNORM, n * 0.5 + 0.5), TS_IMPOSTOR_MIPS levels, sampled
/// linearly between texels and mips, clamped at the edges. Bound for the
/// passes that draw the tier.
#define TS_BINDING_CROWD_IMPOSTOR_ALBEDO 51
#define TS_BINDING_CROWD_IMPOSTOR_NORMAL 52
/// A card's indices: two triangles over its four corners
/// (tsCrowdImpostorIndex).
#define TS_CROWD_IMPOSTOR_INDICES 6u

/// The indirect buffer (uint words): per list an indexed draw command
/// (5 words: indexCount, instanceCount, firstIndex, vertexOffset,
/// firstInstance), then the near skin dispatch (3 words: x = near slots
/// used, 1, 1), then the near slot counter.
#define TS_CROWD_ARG_DRAW_WORDS 5u
#define TS_CROWD_ARG_DISPATCH (TS_CROWD_LISTS * TS_CROWD_ARG_DRAW_WORDS)
#define TS_CROWD_ARG_WORDS (TS_CROWD_ARG_DISPATCH + 4u)

#endif
