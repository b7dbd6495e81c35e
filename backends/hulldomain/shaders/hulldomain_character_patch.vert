#version 450
// hulldomain control points: one invocation per cage vertex (indexed draw,
// so the post-transform cache runs it once per vertex, not per triangle).
// Two-pass: fetches the animated vertex once, a single 128-bit load, and
// decompresses it. Single-pass: hands the index on; the evaluation stage
// skins every tessellated vertex itself.
#extension GL_GOOGLE_include_directive : require
#include "character_common.glsl"

#if defined(TS_CROWD)
// An instanced crowd's near tier: the instance's list entry gives its
// compressed cage's slot (crowd_skin.comp wrote it) and its
// placement.
layout(std430, set = 0, binding = TS_BINDING_CROWD_NEAR) readonly buffer NearBlock {
    uvec4 nearCages[];
};
layout(location = 0) out vec3 outPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
layout(location = 4) out uvec4 outEntry; // CrowdListEntry
void main() {
    // firstInstance is the list's base: gl_InstanceIndex is the entry.
    uint entryIndex = uint(gl_InstanceIndex);
    CrowdListEntry entry = crowdLists[entryIndex];
    // Decompressing needs only the creature's box and uv range; the hull
    // stage selects the rest once per patch.
    CrowdCharacter c = uCrowd.characters[min(tsCrowdInstance(entry.instance).ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
    uCharacter.boxMin = c.boxMin;
    uCharacter.boxMax = c.boxMax;
    uCharacter.uvRange = c.uvRange;
    CageSample s = tsDecompressCageSample(nearCages[entry.slot * uCrowd.flags.z + uint(gl_VertexIndex)]);
    outPosition = s.position;
    outNormal = s.normal;
    outTangent = s.tangent;
    outUv = s.uv;
    outEntry = tsCrowdEntryBits(entry);
}
#elif defined(TS_SINGLE_PASS)
layout(location = 0) out uint outIndex;
void main() {
    outIndex = uint(gl_VertexIndex);
}
#else
layout(std430, set = 0, binding = TS_BINDING_COMPRESSED) readonly buffer CompressedBlock {
    uvec4 compressed[];
};
layout(location = 0) out vec3 outPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
void main() {
    CageSample s = tsDecompressCageSample(compressed[gl_VertexIndex]);
    outPosition = s.position;
    outNormal = s.normal;
    outTangent = s.tangent;
    outUv = s.uv;
}
#endif
