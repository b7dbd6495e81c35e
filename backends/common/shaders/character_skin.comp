#version 450
// Pass 1 of the two-pass characters on the backends with compute (hulldomain,
// meshshader): skins each control-cage vertex once per frame and stores it as
// the paper's 128-bit compressed vertex.
#extension GL_GOOGLE_include_directive : require
#include "character_common.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = TS_BINDING_CAGE_VERTICES) readonly buffer CageBlock {
    CharacterVertex cage[];
};
layout(std430, set = 0, binding = TS_BINDING_COMPRESSED) writeonly buffer CompressedBlock {
    uvec4 compressed[];
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCharacter.counts.x) return;
    compressed[i] = tsCompressCageSample(tsSkinCageVertex(cage[i]));
}
