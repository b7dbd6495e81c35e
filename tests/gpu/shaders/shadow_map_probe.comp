#version 450
// Samples a gpu::ShadowMapArray through its comparison sampler at the probes
// tests/gpu/shadow_map_array_test.cpp gives (uv, layer, reference depth).
layout(local_size_x = 16) in;

layout(set = 0, binding = 0) uniform sampler2DArrayShadow shadowMap;
layout(std430, set = 0, binding = 1) readonly buffer Probes {
    vec4 probes[]; // xy: uv, z: layer, w: reference depth
};
layout(std430, set = 0, binding = 2) writeonly buffer Results {
    float results[]; // 1: lit, 0: shadowed
};
layout(push_constant) uniform Push {
    uvec4 count;
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= count.x) return;
    results[i] = texture(shadowMap, probes[i]);
}
