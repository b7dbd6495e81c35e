#version 450
// streamout.crowd.bin, geometry stage: one stream-out pass per tier (the
// push constant's x) and creature sorts the survivors into list (tier,
// creature), as the Froblins did with successive stream-out passes (the
// mesh tiers' passes read the split's mesh survivors, the impostor tier's
// every survivor). A
// survivor in the tier emits its entry; one fading out of the tier (its
// previous tier, with fade frames left) emits the fading copy, with the
// rest of the coverage. The pass's transform-feedback query counts what was
// written: the list's instance count.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "crowd_common.glsl"
#include "streamout_crowd.glsl"

layout(points) in;
layout(points, max_vertices = 2) out;

layout(location = 0) in uvec2 vSurvivor[];
// CrowdListEntry (instance, slot, coverage, flags); the slot is 0 here: the
// near tier's slots are the near pass's records.
layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out uvec4 outEntry;

void main() {
    uint tier = soCrowd.x;
    uint instance = vSurvivor[0].x;
    uint next = vSurvivor[0].y;
    float coverage = tsLodCoverage(next, uCrowd.lod);
    if (tsLodStateTier(next) == tier) {
        outEntry = uvec4(instance, 0u, floatBitsToUint(coverage), tier << 8u);
        EmitVertex();
        EndPrimitive();
    }
    if (tsLodStateFade(next) > 0u && tsLodStatePrevious(next) == tier) {
        outEntry = uvec4(instance, 0u, floatBitsToUint(1.0 - coverage), 1u | (tier << 8u));
        EmitVertex();
        EndPrimitive();
    }
}
