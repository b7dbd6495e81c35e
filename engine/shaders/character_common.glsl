// character_common.glsl: the character passes' uniforms, skinning and the
// compressed animated vertex (the paper's "Rendering Animated, Tessellated
// Characters"). Pass 1 of the two-pass path calls tsSkinCageVertex and
// tsCompressCageSample once per cage vertex; the single-pass path calls
// tsSkinCageVertex for each corner of each tessellated vertex.
#ifndef CHARACTER_COMMON_GLSL
#define CHARACTER_COMMON_GLSL
#include "tessera/shaders/CharacterUniforms.h"
#include "tessera/shaders/CompressedVertex.h"

#ifdef TS_CROWD
// Instanced crowd draws: uCharacter is filled per invocation from the
// instance's list entry and the palette comes from the baked clips
// (crowd_common.glsl), so every function below serves both.
#include "crowd_common.glsl"
#else
layout(std140, set = 0, binding = TS_BINDING_CHARACTER) uniform CharacterBlock {
    CharacterUniforms uCharacter;
};
layout(std140, set = 0, binding = TS_BINDING_CHARACTER_PALETTE) uniform PaletteBlock {
    CharacterPalette uPalette;
};
mat4 tsPaletteJoint(uint joint) {
    return uPalette.joints[joint];
}
#endif

// One animated cage vertex in model space: what the evaluation interpolates.
struct CageSample {
    vec3 position;
    vec3 normal;
    vec3 tangent;
    vec2 uv;
};

// Linear blend skinning, as character::skinVertex does it on the CPU (the
// tests' reference): the weights arrive normalised (GpuCharacter), tangents go
// through the blended 3x3 and normals through its cofactor matrix, which stays
// right under the non-uniform scale glTF animations may key; both renormalised.
CageSample tsSkinCageVertex(CharacterVertex v) {
    mat4 m = tsPaletteJoint(v.joints.x) * v.weights.x + tsPaletteJoint(v.joints.y) * v.weights.y +
             tsPaletteJoint(v.joints.z) * v.weights.z + tsPaletteJoint(v.joints.w) * v.weights.w;
    mat3 linear = mat3(m);
    mat3 cofactor = mat3(cross(linear[1], linear[2]), cross(linear[2], linear[0]), cross(linear[0], linear[1]));
    if (determinant(linear) < 0.0) cofactor = -cofactor;
    CageSample s;
    s.position = (m * vec4(v.positionU.xyz, 1.0)).xyz;
    s.normal = normalize(cofactor * v.normalV.xyz);
    s.tangent = normalize(linear * v.tangent.xyz);
    s.uv = vec2(v.positionU.w, v.normalV.w);
    return s;
}

// The 128-bit vertex of CompressedVertex.h, in this character's box and uv range.
uvec4 tsCompressCageSample(CageSample s) {
    return tsPackVertex(s.position, s.normal, s.tangent, s.uv, uCharacter.boxMin.xyz, uCharacter.boxMax.xyz,
                        uCharacter.uvRange.xy, uCharacter.uvRange.zw);
}

CageSample tsDecompressCageSample(uvec4 packed) {
    CageSample s;
    tsUnpackVertex(packed, uCharacter.boxMin.xyz, uCharacter.boxMax.xyz, uCharacter.uvRange.xy, uCharacter.uvRange.zw,
                   s.position, s.normal, s.tangent, s.uv);
    return s;
}

// A bind-pose vertex from the five RGBA32UI texels it occupies in a texel
// buffer (the emulated backends' vertex-texture fetch of the cage).
CharacterVertex tsCageVertexFromTexels(uvec4 t0, uvec4 t1, uvec4 t2, uvec4 t3, uvec4 t4) {
    CharacterVertex v;
    v.positionU = uintBitsToFloat(t0);
    v.normalV = uintBitsToFloat(t1);
    v.tangent = uintBitsToFloat(t2);
    v.joints = t3;
    v.weights = uintBitsToFloat(t4);
    return v;
}

#endif
