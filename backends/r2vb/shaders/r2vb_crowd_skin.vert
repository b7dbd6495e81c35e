#version 450
// Pass crowd.nearSkin (r2vb): the near tier's pass 1, as the character
// path's r2vb skin pass (r2vb_character_skin.vert) but instanced over the
// near slots: drawn indirectly by the draws crowd.nearSlots wrote, one per
// slot, whose vertices are its creature's cage in the crowd's vertex stream
// (firstVertex: the cage's first vertex) and whose instance is the slot. Each
// point skins its vertex from the instance's baked clip, compresses it to the
// 128-bit format and lands on texel slot * nearStride + vertex of the cage
// target, which is then copied into crowd.nearCages() (the R2VB step).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "character_common.glsl"
#include "r2vb_crowd.glsl"

layout(set = 0, binding = TS_BINDING_CROWD_SLOTS) uniform usamplerBuffer uNearSlots;

// The bind-pose cage as an ordinary vertex stream (CharacterVertex).
layout(location = 0) in vec4 inPositionU;
layout(location = 1) in vec4 inNormalV;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in uvec4 inJoints;
layout(location = 4) in vec4 inWeights;

layout(location = 0) flat out uvec4 outPacked;

void main() {
    uint slot = uint(gl_InstanceIndex);
    uvec4 bits = texelFetch(uNearSlots, int(slot));
    CrowdNearSlot s;
    s.instance = bits.x;
    s.flags = bits.y;
    s.coverage = uintBitsToFloat(bits.z);
    s.level = uintBitsToFloat(bits.w);
    tsCrowdSelectAtLevel(tsCrowdNearEntry(s, slot), s.level);
    CrowdCharacter c = uCrowd.characters[min(tsCrowdInstance(s.instance).ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
    CharacterVertex v;
    v.positionU = inPositionU;
    v.normalV = inNormalV;
    v.tangent = inTangent;
    v.joints = inJoints;
    v.weights = inWeights;
    outPacked = tsCompressCageSample(tsSkinCageVertex(v));
    gl_PointSize = 1.0;
    gl_Position = r2vbCrowdTexelPosition(slot * uCrowd.flags.z + (uint(gl_VertexIndex) - c.mesh.x));
}
