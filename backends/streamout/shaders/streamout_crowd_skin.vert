#version 450
// streamout.crowd.skin: the near tier's pass 1, one creature at a time. The
// cage's vertices are drawn as points, instanced over the creature's near
// list (the per-instance stream; the instance count is the list's count,
// copied from its transform-feedback query into the indirect command), and
// each invocation skins its vertex from the instance's baked clip and
// streams out the compressed vertex (tsCompressCageSample). Capture is
// instance-major and every instance draws nearStride vertices (zeros past
// the creature's cage); every creature's draw appends in one transform-
// feedback session, so near entry k of creature c lands in slot (entries of
// creatures before c) + k, at texel slot * nearStride + v: the slot the slots
// pass gave it.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "character_common.glsl"
#include "streamout_crowd.glsl"

layout(location = 0) in uvec4 inEntry; // CrowdListEntry of list (near, creature), per instance
// The crowd's cages, CharacterVertex as 5 RGBA32UI texels (creature c's from soCrowd.z).
layout(set = 0, binding = TS_BINDING_CROWD_VERTICES) uniform usamplerBuffer uCageVertices;

layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out uvec4 outPacked;

CharacterVertex cageVertex(uint v) {
    int t = int(soCrowd.z + v) * 5;
    CharacterVertex vertex;
    vertex.positionU = uintBitsToFloat(texelFetch(uCageVertices, t));
    vertex.normalV = uintBitsToFloat(texelFetch(uCageVertices, t + 1));
    vertex.tangent = uintBitsToFloat(texelFetch(uCageVertices, t + 2));
    vertex.joints = texelFetch(uCageVertices, t + 3);
    vertex.weights = uintBitsToFloat(texelFetch(uCageVertices, t + 4));
    return vertex;
}

void main() {
    uint v = uint(gl_VertexIndex);
    uvec4 packed = uvec4(0u);
    if (v < uCrowd.characters[soCrowd.y].mesh.y) {
        CrowdListEntry entry = tsCrowdEntry(inEntry);
        // Skinning does not depend on the level (only the evaluation does).
        tsCrowdSelectAtLevel(entry, 1.0);
        packed = tsCompressCageSample(tsSkinCageVertex(cageVertex(v)));
    }
    outPacked = packed;
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
