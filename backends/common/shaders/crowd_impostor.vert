#version 450
// The crowd's impostor tier on the backends with a vertex stage (r2vb,
// streamout, hulldomain): one card per entry of an impostor list. One
// indexed, instanced draw per list (creature): the card's six indices over
// its four corners (gl_VertexIndex is the corner), the list's entries the
// per-instance stream (firstInstance: the list's region), exactly as
// crowd_mesh.vert draws the middle and far tiers. The corners are placed by
// crowd_impostor.glsl, which meshshader's mesh stage shares.
// TS_CROWD_TEXELS: instances and clips from texel buffers (the emulated
// backends).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#include "common_frame.glsl"
#include "crowd_impostor.glsl"

layout(location = 0) in uvec4 inEntry; // CrowdListEntry, per instance

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec2 outUv;
layout(location = 2) flat out uvec4 outCard;      // tsCrowdImpostorFragmentCard()
layout(location = 3) flat out vec4 outCrowdLod;   // tsCrowdFragmentLod()
layout(location = 4) flat out vec4 outCrowdShade; // tsCrowdFragmentShade()

void main() {
    CrowdListEntry entry = tsCrowdEntry(inEntry);
    // The entry's fade, tier and tint, for the fragments (no near level).
    tsCrowdSelectAtLevel(entry, 1.0);
    CrowdInstance instance = tsCrowdInstance(entry.instance);
    CrowdImpostorCard card = tsCrowdImpostorCard(instance);
    vec3 world = tsCrowdImpostorCorner(instance, card, uint(gl_VertexIndex), outUv);
    outWorld = world;
    outCard = tsCrowdImpostorFragmentCard(card, instance);
    outCrowdLod = tsCrowdFragmentLod();
    outCrowdShade = tsCrowdFragmentShade();
    gl_Position = frame.viewProjection * vec4(world, 1.0);
}
