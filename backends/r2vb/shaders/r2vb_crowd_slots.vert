#version 450
// Pass crowd.nearSlots (r2vb): one point per near slot s. Slot s is the
// near tier's element s overall (every creature's, fading copies included),
// found in the histogram pyramid's near channel. The point writes the slot's
// CrowdNearSlot (flags 0 when unused) and the skin pass's indirect draw for
// it (VkDrawIndirectCommand: the creature's cage vertices from its first
// one in the crowd's vertex stream, one instance: firstInstance = s; no
// vertices when unused).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#define R2VB_CROWD_STATE 1
#define R2VB_CROWD_PYRAMID 1
#include "crowd_common.glsl"
#include "r2vb_crowd.glsl"

layout(location = 0) flat out uvec4 outRecord;
layout(location = 1) flat out uvec4 outSkin;

void main() {
    uint s = uint(gl_VertexIndex);
    outRecord = uvec4(0u);
    outSkin = uvec4(0u, 0u, 0u, s);
    if (s < min(r2vbPyramidTotal(TS_LOD_NEAR), uCrowd.counts.z)) {
        uint i = r2vbPyramidFind(TS_LOD_NEAR, s);
        CrowdListEntry entry = r2vbCrowdEntry(i, TS_LOD_NEAR, s);
        CrowdInstance instance = tsCrowdInstance(i);
        CrowdCharacter c = uCrowd.characters[min(instance.ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
        outRecord = uvec4(i, entry.flags | 0x80000000u, floatBitsToUint(entry.coverage),
                          floatBitsToUint(tsCrowdNearLevel(instance)));
        outSkin = uvec4(c.mesh.y, 1u, c.mesh.x, s);
    }
    gl_PointSize = 1.0;
    gl_Position = r2vbCrowdTexelPosition(s);
}
