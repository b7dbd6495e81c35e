#version 450
// shadow_cascades.glsl against the CPU (tests/gpu/shadow_cascades_test.cpp):
// for each probe point, the cascade it selects, its map coordinate and the
// sunlight it keeps from a gpu::ShadowMapArray.
#extension GL_GOOGLE_include_directive : require
#include "shadow_cascades.glsl"

layout(local_size_x = 16) in;

layout(std140, set = 0, binding = 0) uniform CascadeBlock {
    ShadowCascadeUniforms uCascades;
};
layout(set = 0, binding = 1) uniform sampler2DArrayShadow uShadowMap;
layout(std430, set = 0, binding = 2) readonly buffer Probes {
    vec4 probes[]; // xyz: world position, w: view depth
};
layout(std430, set = 0, binding = 3) writeonly buffer Results {
    vec4 results[]; // xyz: map coordinate (uv, reference), w: cascade index + the sunlight kept (0..1) / 2
};
layout(push_constant) uniform Push {
    uvec4 count;
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count.x) return;
    vec3 world = probes[i].xyz;
    float viewDepth = probes[i].w;
    const vec3 up = vec3(0.0, 1.0, 0.0);
    uint index = tsShadowCascadeIndex(uCascades.farDistances, uint(uCascades.params.x), viewDepth);
    bool inside = index < uint(uCascades.params.x);
    vec3 coord = inside ? tsShadowMapCoord(uCascades, index, world, up) : vec3(-1.0);
    float lit = inside ? tsShadowTaps(uShadowMap, index, coord, uCascades.params.y, int(uCascades.pcf.x)) : 1.0;
    results[i] = vec4(coord, float(index) + 0.5 * lit);
}
