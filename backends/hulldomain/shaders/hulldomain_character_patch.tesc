#version 450
// hulldomain hull stage for characters: the superprimitive is the cage
// triangle, passed through; continuous tessellation sets one level for the
// whole draw (the paper's per-draw level), up to 64.
#extension GL_GOOGLE_include_directive : require
#include "character_common.glsl"
#include "shadow_caster.glsl"

layout(vertices = 3) out;

#ifdef TS_SINGLE_PASS
layout(location = 0) in uint inIndex[];
layout(location = 0) out uint outIndex[];
#else
layout(location = 0) in vec3 inPosition[];
layout(location = 1) in vec3 inNormal[];
layout(location = 2) in vec3 inTangent[];
layout(location = 3) in vec2 inUv[];
layout(location = 0) out vec3 outPosition[];
layout(location = 1) out vec3 outNormal[];
layout(location = 2) out vec3 outTangent[];
layout(location = 3) out vec2 outUv[];
#endif
#ifdef TS_CROWD
layout(location = 4) in uvec4 inEntry[]; // CrowdListEntry
// The instance, read once per patch here and handed to every evaluated
// point (the domain stage reads no crowd buffer).
layout(location = 5) patch out vec4 outWorld[4];
layout(location = 9) patch out vec4 outDisplacement;
layout(location = 10) patch out vec4 outCrowdLod;
layout(location = 11) patch out vec4 outCrowdShade;
#endif

void main() {
#ifdef TS_CROWD
    // The instance's own level (its size on screen, within the frame's
    // cap): selected once per patch, by the invocation that sets the levels.
    if (gl_InvocationID == 0) {
        tsCrowdSelect(tsCrowdEntry(inEntry[0]));
        for (int c = 0; c < 4; ++c) outWorld[c] = uCharacter.world[c];
        outDisplacement = uCharacter.displacement;
        outCrowdLod = tsCrowdFragmentLod();
        outCrowdShade = tsCrowdFragmentShade();
    }
#endif
#ifdef TS_SINGLE_PASS
    outIndex[gl_InvocationID] = inIndex[gl_InvocationID];
#else
    outPosition[gl_InvocationID] = inPosition[gl_InvocationID];
    outNormal[gl_InvocationID] = inNormal[gl_InvocationID];
    outTangent[gl_InvocationID] = inTangent[gl_InvocationID];
    outUv[gl_InvocationID] = inUv[gl_InvocationID];
#endif
    if (gl_InvocationID == 0) {
        float level = uCharacter.displacement.z;
#ifdef TS_CROWD
        // A caster outside the cascade's reach: a level of 0 drops the patch
        // before the tessellator (the crowd's caster variant only).
        if (tsShadowCasterCulled(tsCrowdInstance(tsCrowdEntry(inEntry[0]).instance).sphere)) level = 0.0;
#endif
        gl_TessLevelOuter[0] = level;
        gl_TessLevelOuter[1] = level;
        gl_TessLevelOuter[2] = level;
        gl_TessLevelInner[0] = level;
    }
}
