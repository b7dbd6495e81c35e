// character_eval.glsl: the evaluation shader of the paper's Listing 8, shared
// by hulldomain's tessellation evaluation stage and the emulated backends'
// evaluation vertex shader: interpolating planar subdivision (positions,
// normals, tangents and uvs interpolate linearly over the cage triangle) plus
// scalar displacement along the normalised interpolated normal, with the
// map's exact scale and bias. The baker (tools/creature) uses the same surface.
#ifndef CHARACTER_EVAL_GLSL
#define CHARACTER_EVAL_GLSL
#include "character_common.glsl"

layout(set = 0, binding = TS_BINDING_DISPLACEMENT) uniform sampler2D uDisplacementMap;

struct CharacterPoint {
    vec3 world;    // displaced position, world space
    vec3 normal;   // interpolated cage normal, world space (the normal map's frame)
    vec3 tangent;  // interpolated cage tangent, world space
    vec2 uv;
};

// bary = (u, v, 1 - u - v) weights corners a, b, c. `precise` keeps the
// compiler from contracting the sums into FMAs: a point on an edge shared by
// two triangles is then computed from the same two products in either
// triangle (the third weight is exactly 0), so both sides agree bit for bit
// and the displaced surface stays watertight.
CharacterPoint tsEvaluateCharacter(vec3 bary, CageSample a, CageSample b, CageSample c) {
    precise vec3 position = a.position * bary.x + b.position * bary.y + c.position * bary.z;
    precise vec3 normal = a.normal * bary.x + b.normal * bary.y + c.normal * bary.z;
    precise vec2 uv = a.uv * bary.x + b.uv * bary.y + c.uv * bary.z;
    vec3 tangent = a.tangent * bary.x + b.tangent * bary.y + c.tangent * bary.z;
    normal = normalize(normal);
    float sampleValue = textureLod(uDisplacementMap, uv, 0.0).r;
    precise vec3 displaced = position + (sampleValue * uCharacter.displacement.x + uCharacter.displacement.y) * normal;

    CharacterPoint p;
    p.world = (uCharacter.world * vec4(displaced, 1.0)).xyz;
    p.normal = normalize(mat3(uCharacter.worldNormal) * normal);
    p.tangent = mat3(uCharacter.world) * tangent;
    p.uv = uv;
    return p;
}

#endif
