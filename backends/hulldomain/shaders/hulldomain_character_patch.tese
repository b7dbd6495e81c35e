#version 450
// hulldomain domain stage for characters: the paper's Listing 8 evaluation
// (character_eval.glsl) at each tessellated point. The emulated backends run
// the same function on the same points in character_emulated.vert.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "shadow_caster.glsl"
#include "character_eval.glsl"

layout(triangles, fractional_odd_spacing, ccw) in;

#ifdef TS_SINGLE_PASS
layout(std430, set = 0, binding = TS_BINDING_CAGE_VERTICES) readonly buffer CageBlock {
    CharacterVertex cage[];
};
layout(location = 0) in uint inIndex[];
#else
layout(location = 0) in vec3 inPosition[];
layout(location = 1) in vec3 inNormal[];
layout(location = 2) in vec3 inTangent[];
layout(location = 3) in vec2 inUv[];
#endif

#ifdef TS_CROWD
layout(location = 5) patch in vec4 inWorld[4];
layout(location = 9) patch in vec4 inDisplacement;
layout(location = 10) patch in vec4 inCrowdLod;
layout(location = 11) patch in vec4 inCrowdShade;
layout(location = 4) flat out vec4 outCrowdLod;
layout(location = 5) flat out vec4 outCrowdShade;
#endif

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;

CageSample corner(int i) {
#ifdef TS_SINGLE_PASS
    // The brute-force path: every tessellated vertex animates all three
    // superprimitive vertices.
    return tsSkinCageVertex(cage[inIndex[i]]);
#else
    CageSample s;
    s.position = inPosition[i];
    s.normal = inNormal[i];
    s.tangent = inTangent[i];
    s.uv = inUv[i];
    return s;
#endif
}

void main() {
    // w from u and v exactly as the emulated path computes it, so both get
    // the same weights from the same (u, v).
    vec3 bary = vec3(gl_TessCoord.x, gl_TessCoord.y, 1.0 - gl_TessCoord.x - gl_TessCoord.y);
#ifdef TS_CROWD
    // What tsEvaluateCharacter reads of the instance, from the hull stage.
    uCharacter.world = mat4(inWorld[0], inWorld[1], inWorld[2], inWorld[3]);
    uCharacter.worldNormal = uCharacter.world / dot(inWorld[0].xyz, inWorld[0].xyz);
    uCharacter.displacement = inDisplacement;
    outCrowdLod = inCrowdLod;
    outCrowdShade = inCrowdShade;
#endif
    CharacterPoint p = tsEvaluateCharacter(bary, corner(0), corner(1), corner(2));
    outWorld = p.world;
    outNormal = p.normal;
    outTangent = p.tangent;
    outUv = p.uv;
    gl_Position = tsClipPosition(vec4(p.world, 1.0));
}
