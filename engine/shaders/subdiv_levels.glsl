// subdiv_levels.glsl: a domain's tessellation levels for this frame, or
// culled: what hulldomain's hull stage and the emulated backends' factor
// passes compute per domain, from the same shared functions
// (SubdivLayout.h), so every backend tessellates a domain alike.
#ifndef SUBDIV_LEVELS_GLSL
#define SUBDIV_LEVELS_GLSL
#include "subdiv_eval.glsl"

layout(set = 0, binding = TS_BINDING_SUBDIV_SUPPORT) uniform usamplerBuffer subdivSupport;

// False when the domain is a hole or out of view (its levels are then 0).
bool tsSubdivLevels(uint domainIndex, out vec4 outer, out vec2 inner) {
    SubdivDomain d = tsSubdivLoadDomain(domainIndex);
    outer = vec4(0.0);
    inner = vec2(0.0);
    if ((d.topology.w & TS_SUBDIV_DOMAIN_HOLE) != 0u) return false;
    // The support's box (the base vertices are the first refined points).
    vec3 lo = vec3(3.4e38), hi = vec3(-3.4e38);
    for (uint k = 0u; k < d.topology.z; ++k) {
        vec3 p = texelFetch(subdivPoints, int(texelFetch(subdivSupport, int(d.topology.y + k)).r)).xyz;
        lo = min(lo, p);
        hi = max(hi, p);
    }
    if (!tsSubdivBoxVisible(lo, hi, subdiv)) return false;
    tsSubdivDomainLevels(tsSubdivCornerLevels(d), outer, inner);
    return true;
}

#endif
