#version 450
// streamout.crowd.commands: one point per (creature, near slot), vertex
// c * slots + s, no vertex buffer. It reads slot s's record (a texel buffer
// over what the slots pass streamed out) and streams out the slot's indexed
// indirect command for creature c's near draw (tsCrowdNearCommand: empty
// unless the slot is in use by an instance of c), 8 words each, so vertex v
// lands at word 8 v = tsCrowdNearCommandBase(c, s, slots).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "crowd_common.glsl"

layout(set = 0, binding = TS_BINDING_CROWD_SLOTS) uniform usamplerBuffer uNearSlots; // CrowdNearSlot per slot

layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 32) out uvec4 outCommand;
layout(location = 1, xfb_buffer = 0, xfb_offset = 16) out uvec4 outFirstInstance; // and 3 zero words

void main() {
    uint slots = max(uCrowd.counts.z, 1u);
    uint creature = uint(gl_VertexIndex) / slots;
    uint slot = uint(gl_VertexIndex) - creature * slots;
    uvec4 bits = texelFetch(uNearSlots, int(slot));
    CrowdNearSlot record;
    record.instance = bits.x;
    record.flags = bits.y;
    record.coverage = uintBitsToFloat(bits.z);
    record.level = uintBitsToFloat(bits.w);
    bool used = (bits.y & 0x80000000u) != 0u;
    uint slotCreature = used ? tsCrowdInstance(bits.x).ids.y : TS_CROWD_MAX_CHARACTERS;
    uint firstInstance;
    outCommand = tsCrowdNearCommand(uCrowd, record, slotCreature, creature, slot, firstInstance);
    outFirstInstance = uvec4(firstInstance, 0u, 0u, 0u);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
