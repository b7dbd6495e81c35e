#version 450
// The crowd near tier's pass 1 on the backends with compute (hulldomain,
// meshshader; ComputeCrowdCullPass), dispatched indirectly: one workgroup
// per near slot the culling pass filled. Skins the instance's cage from its
// baked clip into the paper's 128-bit compressed vertices, which the
// tessellated draw (hull/domain or task/mesh) then fetches once per cage
// vertex it reads.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#include "character_common.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = TS_BINDING_CROWD_VERTICES) readonly buffer CrowdVertexBlock {
    CharacterVertex crowdVertices[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_NEAR) writeonly buffer NearBlock {
    uvec4 nearCages[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_SLOTS) readonly buffer SlotBlock {
    uvec2 nearSlots[];
};

void main() {
    uint slot = gl_WorkGroupID.x;
    if (slot >= uCrowd.counts.z) return;
    uvec2 owner = nearSlots[slot];
    CrowdListEntry entry;
    entry.instance = owner.x;
    entry.slot = slot;
    entry.coverage = 1.0;
    entry.flags = TS_LOD_NEAR << 8u;
    tsCrowdSelect(entry);
    CrowdCharacter c = uCrowd.characters[owner.y];
    for (uint v = gl_LocalInvocationID.x; v < c.mesh.y; v += 64u)
        nearCages[slot * uCrowd.flags.z + v] = tsCompressCageSample(tsSkinCageVertex(crowdVertices[c.mesh.x + v]));
}
