#version 450
// Sets the patch's levels from push constants: the capture feeds the
// fixed-function tessellator exactly the factors under test.
layout(vertices = 1) out;
layout(push_constant) uniform Levels {
    vec4 outer;
    vec4 inner;
} levels;

void main() {
    gl_TessLevelOuter[0] = levels.outer.x;
    gl_TessLevelOuter[1] = levels.outer.y;
    gl_TessLevelOuter[2] = levels.outer.z;
    gl_TessLevelOuter[3] = levels.outer.w;
    gl_TessLevelInner[0] = levels.inner.x;
    gl_TessLevelInner[1] = levels.inner.y;
}
