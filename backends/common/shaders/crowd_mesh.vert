#version 450
// An instanced crowd's middle and far tiers: the cage (middle) or the far
// mesh, skinned here from the instance's baked clip (no compressed pre-pass:
// these instances are many and small), lit by the normal map in
// character.frag. One indexed, instanced draw per list (tier, creature);
// firstInstance is the list's base, so gl_InstanceIndex is the entry, and
// vertexOffset the mesh's first vertex in the crowd's vertex buffer.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#include "common_frame.glsl"
#include "character_common.glsl"

layout(std430, set = 0, binding = TS_BINDING_CROWD_VERTICES) readonly buffer CrowdVertexBlock {
    CharacterVertex crowdVertices[];
};

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out uint outEntry;

void main() {
    uint entryIndex = uint(gl_InstanceIndex);
    tsCrowdSelect(crowdLists[entryIndex]);
    CageSample s = tsSkinCageVertex(crowdVertices[gl_VertexIndex]);
    vec4 world = uCharacter.world * vec4(s.position, 1.0);
    outWorld = world.xyz;
    outNormal = normalize(mat3(uCharacter.worldNormal) * s.normal);
    outTangent = mat3(uCharacter.world) * s.tangent;
    outUv = s.uv;
    outEntry = entryIndex;
    gl_Position = frame.viewProjection * world;
}
