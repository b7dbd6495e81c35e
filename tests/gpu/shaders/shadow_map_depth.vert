#version 450
// A depth-only caster for tests/gpu/shadow_map_array_test.cpp: one triangle
// covering the whole layer at the pushed depth (no fragment stage).
layout(push_constant) uniform Push {
    vec4 depth; // x: the depth written
};

void main() {
    const vec2 corners[3] = vec2[3](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
    gl_Position = vec4(corners[gl_VertexIndex], depth.x, 1.0);
}
