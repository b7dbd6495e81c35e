// subdiv_refine.glsl: one refined point of a subdivision surface from this
// frame's cage (SubdivLayout.h: per point a stencil record, its entries),
// the weighted sum every backend's refine pass computes with its own
// recirculation (compute, transform feedback, render target), so all three
// produce the same control points from the same data.
#ifndef SUBDIV_REFINE_GLSL
#define SUBDIV_REFINE_GLSL
#include "tessera/shaders/SubdivLayout.h"

layout(set = 0, binding = TS_BINDING_SUBDIV_STENCILS) uniform usamplerBuffer subdivStencils;
layout(set = 0, binding = TS_BINDING_SUBDIV_ENTRIES) uniform usamplerBuffer subdivEntries;
layout(set = 0, binding = TS_BINDING_SUBDIV_CAGE) uniform samplerBuffer subdivCage;

// Point `index` (xyz) with its w (1 for a control point, the LOD radius for
// a corner point).
vec4 tsSubdivRefinePoint(uint index) {
    uvec4 stencil = texelFetch(subdivStencils, int(index));
    vec3 sum = vec3(0.0);
    for (uint k = 0u; k < stencil.y; ++k) {
        uvec2 entry = texelFetch(subdivEntries, int(stencil.x + k)).xy;
        sum += uintBitsToFloat(entry.y) * texelFetch(subdivCage, int(entry.x)).xyz;
    }
    return vec4(sum, uintBitsToFloat(stencil.z));
}

#endif
