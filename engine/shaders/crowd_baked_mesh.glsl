// crowd_baked_mesh.glsl: a vertex of an instanced crowd's middle or far tier
// from the baked vertex animation (character::appendBakedVertices): the mesh
// pre-skinned at every baked frame in the 128-bit vertex, two fetches and a
// blend per vertex instead of skinning four joints of two baked frames.
// Shared by crowd_mesh.vert (one vertex per invocation) and the meshshader
// backend's meshlet mesh stage (a meshlet's vertices per workgroup), so both
// place the same points. Needs TS_CROWD (crowd_common.glsl).
#ifndef CROWD_BAKED_MESH_GLSL
#define CROWD_BAKED_MESH_GLSL
#include "character_common.glsl"

layout(set = 0, binding = TS_BINDING_CROWD_BAKED_VERTICES) uniform usamplerBuffer uBakedVertices;
layout(set = 0, binding = TS_BINDING_CROWD_CLIP_MESHES) uniform usamplerBuffer uClipMeshes;

// Where an instance's mesh sits in the baked vertices and its frame pair.
struct CrowdBakedMesh {
    uint first;    // texel of the clip's first frame
    uint vertices; // the mesh's vertices (a frame's texels)
    uint frame0;
    uint frame1;
    float blend;   // weight of frame1
};

// The mesh list entry `entry` draws (the cage for the middle tier, the far
// mesh for the far tier; as shadow casters both tiers draw the far mesh's
// vertices, under the casters' simplified triangles: docs/LOOKS.md, "The
// casters"); tsCrowdSelectAtLevel(entry, ...) comes first (it sets the clip
// and phase).
CrowdBakedMesh tsCrowdBakedMesh(CrowdListEntry entry) {
    CrowdInstance instance = tsCrowdInstance(entry.instance);
    CrowdCharacter c = uCrowd.characters[min(instance.ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
#ifdef TS_SHADOW_CASTER
    bool far = true;
#else
    bool far = ((entry.flags >> 8u) & 255u) == TS_LOD_FAR;
#endif
    uvec4 meshes = texelFetch(uClipMeshes, int(instance.ids.z));
    CrowdBakedMesh m;
    m.vertices = far ? c.mesh.w : c.mesh.y;
    m.first = far ? meshes.y : meshes.x;
    m.blend = tsBakedFramePair(gCrowdClip, gCrowdPhase, m.frame0, m.frame1);
    return m;
}

// Mesh-local vertex `v` of `m`, placed by uCharacter (world space).
struct CrowdBakedPoint {
    vec4 world;
    vec3 normal;
    vec3 tangent;
    vec2 uv;
};

CrowdBakedPoint tsCrowdBakedPoint(CrowdBakedMesh m, uint v) {
    CageSample a = tsDecompressCageSample(texelFetch(uBakedVertices, int(m.first + m.frame0 * m.vertices + v)));
    CageSample b = tsDecompressCageSample(texelFetch(uBakedVertices, int(m.first + m.frame1 * m.vertices + v)));
    vec3 position = mix(a.position, b.position, m.blend);
    vec3 normal = normalize(mix(a.normal, b.normal, m.blend));
    vec3 tangent = mix(a.tangent, b.tangent, m.blend);
    CrowdBakedPoint p;
    p.world = uCharacter.world * vec4(position, 1.0);
    p.normal = normalize(mat3(uCharacter.worldNormal) * normal);
    p.tangent = mat3(uCharacter.world) * tangent;
    p.uv = a.uv;
    return p;
}

#endif
