#version 450
// An instanced crowd's near tier on the emulated backends (r2vb, streamout):
// the paper's Listing 8 evaluation vertex shader in front of the emulated
// tessellator, with every instance at its own continuous level. Each near
// slot is one indexed indirect draw (its command written by the backend's
// own binning pass, tsCrowdNearCommand): the pattern of its level's class is
// the index and per-vertex stream (point codes, TessTrianglePattern.h), and
// the instances are the creature's cage triangles, slot * stride + triangle.
// Each point is placed at the slot's level in the reference tessellator's
// fixed point, so it is hulldomain's gl_TessCoord bit for bit; the corners
// are the slot's compressed cage (the backend's skin pass wrote it).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "common_frame.glsl"
#include "shadow_caster.glsl"
#include "character_eval.glsl"

layout(location = 0) in uint inCode; // the pattern point's code

layout(set = 0, binding = TS_BINDING_CROWD_SLOTS) uniform usamplerBuffer uNearSlots;  // CrowdNearSlot per slot
layout(set = 0, binding = TS_BINDING_CROWD_NEAR) uniform usamplerBuffer uNearCages;   // uvec4 per cage vertex per slot
layout(set = 0, binding = TS_BINDING_CROWD_INDICES) uniform usamplerBuffer uIndices;  // the crowd's index buffer

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
layout(location = 4) flat out vec4 outCrowdLod;
layout(location = 5) flat out vec4 outCrowdShade;

CageSample corner(uint slot, uint index) {
    return tsDecompressCageSample(texelFetch(uNearCages, int(slot * uCrowd.flags.z + index)));
}

void main() {
    uint stride = max(uCrowd.emulated.x, 1u);
    uint slot = uint(gl_InstanceIndex) / stride;
    uint triangle = uint(gl_InstanceIndex) - slot * stride;
    uvec4 bits = texelFetch(uNearSlots, int(slot));
    CrowdNearSlot s;
    s.instance = bits.x;
    s.flags = bits.y;
    s.coverage = uintBitsToFloat(bits.z);
    s.level = uintBitsToFloat(bits.w);
    // A caster outside the cascade's reach: none of its vertices' work.
    if (tsShadowCasterCulled(tsCrowdInstance(s.instance).sphere)) {
        gl_Position = tsCulledPosition();
        return;
    }
    CrowdListEntry entry = tsCrowdNearEntry(s, slot);
    tsCrowdSelectAtLevel(entry, s.level);
    CrowdCharacter c = uCrowd.characters[min(tsCrowdInstance(s.instance).ids.y, TS_CROWD_MAX_CHARACTERS - 1u)];
    int first = int(c.indices.x + 3u * triangle);
    vec2 uv = tsEmuTrianglePoint(inCode, tsEmuTriangleLevel(s.level));
    vec3 bary = vec3(uv.x, uv.y, 1.0 - uv.x - uv.y);
    CharacterPoint p = tsEvaluateCharacter(bary, corner(slot, texelFetch(uIndices, first).x),
                                           corner(slot, texelFetch(uIndices, first + 1).x),
                                           corner(slot, texelFetch(uIndices, first + 2).x));
    outWorld = p.world;
    outNormal = p.normal;
    outTangent = p.tangent;
    outUv = p.uv;
    outCrowdLod = tsCrowdFragmentLod();
    outCrowdShade = tsCrowdFragmentShade();
    gl_Position = tsClipPosition(vec4(p.world, 1.0));
}
