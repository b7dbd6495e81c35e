#version 450
// streamout.crowd.slots: a point per entry of one creature's near list (an
// indirect draw, its count from the list's stream query); each entry
// is appended to the near slot records (every creature's draw in one
// transform-feedback session), so creature c's entries take the slots after
// those of creatures 0..c-1. Entries past the last slot overflow the buffer
// and are dropped, as the contract wants (the budget keeps them within it).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "crowd_common.glsl"

layout(location = 0) in uvec4 inEntry; // CrowdListEntry of list (near, creature)
// CrowdNearSlot (instance, flags | in use, coverage, level).
layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out uvec4 outSlot;

void main() {
    float level = tsCrowdNearLevel(tsCrowdInstance(inEntry.x));
    outSlot = uvec4(inEntry.x, inEntry.w | 0x80000000u, inEntry.z, floatBitsToUint(level));
    // Nothing is rasterised; a point list still needs both.
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
