#version 450
// hulldomain hull stage for subdivision surfaces: one domain per patch, its
// levels from the per-vertex levels of its corners (the second paper's
// section 6.1), culled when a hole or out of view.
#extension GL_GOOGLE_include_directive : require
#include "subdiv_levels.glsl"

layout(vertices = 1) out;
layout(location = 0) in uint inDomain[];
layout(location = 0) patch out uint patchDomain;

void main() {
    patchDomain = inDomain[0];
    vec4 outer;
    vec2 inner;
    tsSubdivLevels(inDomain[0], outer, inner);
    gl_TessLevelOuter[0] = outer.x;
    gl_TessLevelOuter[1] = outer.y;
    gl_TessLevelOuter[2] = outer.z;
    gl_TessLevelOuter[3] = outer.w;
    gl_TessLevelInner[0] = inner.x;
    gl_TessLevelInner[1] = inner.y;
}
