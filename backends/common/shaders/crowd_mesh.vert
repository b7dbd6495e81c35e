#version 450
// An instanced crowd's middle and far tiers on every backend: the cage
// (middle) or the far mesh, lit by the normal map in character.frag. One
// indexed, instanced draw per list (tier, creature): the list's entries are
// the per-instance stream (firstInstance: the list's region), so each
// backend's culling pass, whatever its technique, only has to write entries
// and an instance count. Vertices come from the baked vertex animation
// (character::appendBakedVertices): the mesh pre-skinned at every baked
// frame in the 128-bit vertex, two fetches and a blend per vertex instead
// of skinning four joints of two baked frames. TS_CROWD_TEXELS: instances
// and clips from texel buffers (the emulated backends).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#include "common_frame.glsl"
#include "character_common.glsl"

layout(set = 0, binding = TS_BINDING_CROWD_BAKED_VERTICES) uniform usamplerBuffer uBakedVertices;
layout(set = 0, binding = TS_BINDING_CROWD_CLIP_MESHES) uniform usamplerBuffer uClipMeshes;

layout(location = 0) in uvec4 inEntry; // CrowdListEntry, per instance

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out vec4 outCrowdLod;
layout(location = 5) flat out vec4 outCrowdShade;

void main() {
    CrowdListEntry entry = tsCrowdEntry(inEntry);
    // Middle and far tiers: no near level to compute.
    tsCrowdSelectAtLevel(entry, 1.0);
    CrowdInstance instance = tsCrowdInstance(entry.instance);
    CrowdCharacter c = uCrowd.characters[min(instance.ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
    bool far = ((entry.flags >> 8u) & 255u) == TS_LOD_FAR;
    uint vertices = far ? c.mesh.w : c.mesh.y;
    uvec4 meshes = texelFetch(uClipMeshes, int(instance.ids.z));
    uint first = far ? meshes.y : meshes.x;
    uint frame0, frame1;
    float w = tsBakedFramePair(gCrowdClip, gCrowdPhase, frame0, frame1);
    uint v = uint(gl_VertexIndex);
    CageSample a = tsDecompressCageSample(texelFetch(uBakedVertices, int(first + frame0 * vertices + v)));
    CageSample b = tsDecompressCageSample(texelFetch(uBakedVertices, int(first + frame1 * vertices + v)));
    vec3 position = mix(a.position, b.position, w);
    vec3 normal = normalize(mix(a.normal, b.normal, w));
    vec3 tangent = mix(a.tangent, b.tangent, w);
    vec4 world = uCharacter.world * vec4(position, 1.0);
    outWorld = world.xyz;
    outNormal = normalize(mat3(uCharacter.worldNormal) * normal);
    outTangent = mat3(uCharacter.world) * tangent;
    outUv = a.uv;
    outCrowdLod = tsCrowdFragmentLod();
    outCrowdShade = tsCrowdFragmentShade();
    gl_Position = frame.viewProjection * world;
}
