#version 450
// An instanced crowd's middle and far tiers on every backend: the cage
// (middle) or the far mesh, skinned here from the instance's baked clip (no
// compressed pre-pass: these instances are many and small), lit by the
// normal map in character.frag. One indexed, instanced draw per list (tier,
// creature): the mesh is the per-vertex stream (vertexOffset: its first
// vertex in the crowd's vertex buffer) and the list's entries the
// per-instance stream (firstInstance: the list's region), so each backend's
// culling pass, whatever its technique, only has to write entries and an
// instance count. TS_CROWD_TEXELS: instances and clips from texel buffers
// (the emulated backends).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#include "common_frame.glsl"
#include "character_common.glsl"

layout(location = 0) in vec4 inPositionU;
layout(location = 1) in vec4 inNormalV;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in uvec4 inJoints;
layout(location = 4) in vec4 inWeights;
layout(location = 5) in uvec4 inEntry; // CrowdListEntry, per instance

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out uvec4 outEntry;

void main() {
    tsCrowdSelect(tsCrowdEntry(inEntry));
    CharacterVertex v;
    v.positionU = inPositionU;
    v.normalV = inNormalV;
    v.tangent = inTangent;
    v.joints = inJoints;
    v.weights = inWeights;
    CageSample s = tsSkinCageVertex(v);
    vec4 world = uCharacter.world * vec4(s.position, 1.0);
    outWorld = world.xyz;
    outNormal = normalize(mat3(uCharacter.worldNormal) * s.normal);
    outTangent = mat3(uCharacter.world) * s.tangent;
    outUv = s.uv;
    outEntry = inEntry;
    gl_Position = frame.viewProjection * world;
}
