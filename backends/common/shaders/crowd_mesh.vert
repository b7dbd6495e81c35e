#version 450
// An instanced crowd's middle and far tiers on every backend: the cage
// (middle) or the far mesh, lit by the normal map in character.frag. One
// indexed, instanced draw per list (tier, creature): the list's entries are
// the per-instance stream (firstInstance: the list's region), so each
// backend's culling pass, whatever its technique, only has to write entries
// and an instance count. Vertices come from the baked vertex animation
// (crowd_baked_mesh.glsl, which the meshshader backend's meshlets share).
// TS_CROWD_TEXELS: instances
// and clips from texel buffers (the emulated backends).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#include "common_frame.glsl"
#include "shadow_caster.glsl"
#include "crowd_baked_mesh.glsl"

layout(location = 0) in uvec4 inEntry; // CrowdListEntry, per instance

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out vec4 outCrowdLod;
layout(location = 5) flat out vec4 outCrowdShade;

void main() {
    CrowdListEntry entry = tsCrowdEntry(inEntry);
    // A caster outside the cascade's reach: none of its vertices' work.
    if (tsShadowCasterCulled(tsCrowdInstance(entry.instance).sphere)) {
        gl_Position = tsCulledPosition();
        return;
    }
    // Middle and far tiers: no near level to compute.
    tsCrowdSelectAtLevel(entry, 1.0);
    CrowdBakedPoint p = tsCrowdBakedPoint(tsCrowdBakedMesh(entry), uint(gl_VertexIndex));
    outWorld = p.world.xyz;
    outNormal = p.normal;
    outTangent = p.tangent;
    outUv = p.uv;
    outCrowdLod = tsCrowdFragmentLod();
    outCrowdShade = tsCrowdFragmentShade();
    gl_Position = tsClipPosition(p.world);
}
