#version 450
// streamout.crowd.bin, first stage (the split), geometry stage: one stream-out
// pass per creature copies the survivors that the mesh tiers' lists can take
// (drawn in the near, middle or far tier, or fading out of one) into the
// creature's region of the mesh survivors. Most survivors of a large crowd
// are impostors: the three mesh tiers' bin passes then read this short
// stream instead of every survivor, and only the impostor tier's pass reads
// them all (D3D10 streams one output per pass, so a pass cannot route a
// point to one of several lists).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CrowdLod.h"

layout(points) in;
layout(points, max_vertices = 1) out;

layout(location = 0) in uvec2 vSurvivor[];
layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 8) out uvec2 outSurvivor;

void main() {
    uint next = vSurvivor[0].y;
    bool mesh = tsLodStateTier(next) <= TS_LOD_FAR ||
                (tsLodStateFade(next) > 0u && tsLodStatePrevious(next) <= TS_LOD_FAR);
    if (!mesh) return;
    outSurvivor = vSurvivor[0];
    EmitVertex();
    EndPrimitive();
}
