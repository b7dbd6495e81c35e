#version 450
// Pass crowd.nearCommands (r2vb): two points per (creature, near slot), one
// per texel of its 8-word command (tsCrowdNearCommandBase): the indexed
// draw of the slot's pattern over the creature's cage triangles
// (tsCrowdNearCommand, zero unless the slot is used by that creature), then
// its first instance and three zero words. The slot records arrive as a
// texel buffer, crowd.nearSlots's target copied (the R2VB step).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "crowd_common.glsl"
#include "r2vb_crowd.glsl"

layout(set = 0, binding = TS_BINDING_CROWD_SLOTS) uniform usamplerBuffer uNearSlots;

layout(location = 0) flat out uvec4 outTexel;

void main() {
    uint texel = uint(gl_VertexIndex);
    uint command = texel >> 1u;
    uint slots = max(uCrowd.counts.z, 1u);
    uint creature = command / slots;
    uint slot = command - creature * slots;
    uvec4 bits = texelFetch(uNearSlots, int(slot));
    CrowdNearSlot s;
    s.instance = bits.x;
    s.flags = bits.y;
    s.coverage = uintBitsToFloat(bits.z);
    s.level = uintBitsToFloat(bits.w);
    uint slotCreature = (s.flags & 0x80000000u) != 0u ? tsCrowdInstance(s.instance).ids.y : TS_CROWD_MAX_CHARACTERS;
    uint firstInstance;
    uvec4 draw = tsCrowdNearCommand(uCrowd, s, slotCreature, creature, slot, firstInstance);
    outTexel = (texel & 1u) == 0u ? draw : uvec4(firstInstance, 0u, 0u, 0u);
    gl_PointSize = 1.0;
    gl_Position = r2vbCrowdTexelPosition(texel);
}
