#version 450
// The emulated backends' evaluation vertex shader for characters (the
// paper's Listing 8 in its Direct3D 9/10 form): one invocation per pattern
// point per cage triangle. The pattern (the emulated tessellator's output for
// the draw's continuous level, triangle domain) is the per-vertex stream;
// the cage triangle's three vertex indices are the per-instance stream (the
// paper's BLENDINDICES "index retrieval" mode), and the superprimitive's
// vertices are fetched from a texel buffer (vertex texture / Buffer.Load).
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "shadow_caster.glsl"
#include "character_eval.glsl"

layout(location = 0) in vec2 inDomain;     // (u, v), bit-identical with gl_TessCoord.xy
layout(location = 1) in uvec3 inTriangle;  // the superprimitive's vertex indices

#ifdef TS_SINGLE_PASS
layout(set = 0, binding = TS_BINDING_CAGE_VERTICES) uniform usamplerBuffer uCage;
#else
layout(set = 0, binding = TS_BINDING_COMPRESSED) uniform usamplerBuffer uCompressed;
#endif

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;

CageSample corner(uint index) {
#ifdef TS_SINGLE_PASS
    int t = int(index) * TS_CHARACTER_VERTEX_TEXELS;
    return tsSkinCageVertex(tsCageVertexFromTexels(texelFetch(uCage, t), texelFetch(uCage, t + 1),
                                                   texelFetch(uCage, t + 2), texelFetch(uCage, t + 3),
                                                   texelFetch(uCage, t + 4)));
#else
    return tsDecompressCageSample(texelFetch(uCompressed, int(index)));
#endif
}

void main() {
    vec3 bary = vec3(inDomain.x, inDomain.y, 1.0 - inDomain.x - inDomain.y);
    CharacterPoint p = tsEvaluateCharacter(bary, corner(inTriangle.x), corner(inTriangle.y), corner(inTriangle.z));
    outWorld = p.world;
    outNormal = p.normal;
    outTangent = p.tangent;
    outUv = p.uv;
    gl_Position = tsClipPosition(vec4(p.world, 1.0));
}
