// CharacterUniforms.h: what every character pass reads, host and GLSL alike.
//
// A character draw binds (set 0):
//   TS_BINDING_FRAME (0)            FrameUniforms
//   TS_BINDING_CHARACTER (1)        CharacterUniforms, one per drawn instance
//   TS_BINDING_CHARACTER_PALETTE (2) CharacterPalette: the skinning matrices
//   TS_BINDING_CAGE_VERTICES (3)    the bind-pose cage, CharacterVertex[]
//                                   (storage buffer, or an RGBA32UI texel buffer
//                                   of TS_CHARACTER_VERTEX_TEXELS texels each)
//   TS_BINDING_COMPRESSED (4)       the animated cage, one uvec4 per vertex in the
//                                   128-bit format of CompressedVertex.h
//   TS_BINDING_BASE_COLOR (5), TS_BINDING_NORMAL_MAP (6),
//   TS_BINDING_DISPLACEMENT (7)     the character's maps
#ifndef TESSERA_CHARACTER_UNIFORMS_H
#define TESSERA_CHARACTER_UNIFORMS_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

// The most skinning matrices one character may have (a 16 KiB uniform block:
// within every device's maxUniformBufferRange, and the D3D9-era habit of
// keeping the palette in constants).
#define TS_MAX_CHARACTER_JOINTS 256

// One bind-pose cage vertex as the GPU reads it (80 bytes = 5 texels).
struct CharacterVertex {
    vec4 positionU; // xyz: model-space position, w: u
    vec4 normalV;   // xyz: unit normal, w: v
    vec4 tangent;   // xyz: unit tangent along +u, w: bitangent sign
    uvec4 joints;   // palette indices
    vec4 weights;   // sum to 1
};
TS_CHECK_SIZE(CharacterVertex, 80)
#define TS_CHARACTER_VERTEX_TEXELS 5

struct CharacterUniforms {
    mat4 world;        // model to world
    mat4 worldNormal;  // inverse transpose of world (upper 3x3 used)
    vec4 boxMin;       // xyz: compression box minimum (model space)
    vec4 boxMax;       // xyz: compression box maximum
    vec4 uvRange;      // xy: uv minimum, zw: uv maximum (the compressed uv's range)
    vec4 displacement; // x: scale, y: bias (both 0 with displacement off), z: tessellation level, w: 1 = normal map on
    uvec4 counts;      // x: cage vertices, y: palette size, z: r2vb target width, w: 1 = bitangent is -cross(n, t) for the whole character
    vec4 lod;          // x: coverage in (0, 1] (a cross-fade's share), y: 1 = the fading-out copy, z: LOD tier (CrowdLod.h), w: 1 = tint by tier
};
TS_CHECK_SIZE(CharacterUniforms, 224)

struct CharacterPalette {
    mat4 joints[TS_MAX_CHARACTER_JOINTS];
};
TS_CHECK_SIZE(CharacterPalette, 16384)

TS_NAMESPACE_END

#define TS_BINDING_CHARACTER 1
#define TS_BINDING_CHARACTER_PALETTE 2
#define TS_BINDING_CAGE_VERTICES 3
#define TS_BINDING_COMPRESSED 4
#define TS_BINDING_BASE_COLOR 5
#define TS_BINDING_NORMAL_MAP 6
#define TS_BINDING_DISPLACEMENT 7

#endif
