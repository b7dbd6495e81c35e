#version 450
// The terrain resolve as a fullscreen pass (terrain_resolve.glsl), for the
// backends without compute. It reads a copy of what the main pass left in
// the target; the pipeline's depth test (GREATER than the far plane) keeps
// it to the pixels something covered, so the sky, which the sky pass drew,
// costs nothing here.
#extension GL_GOOGLE_include_directive : require
#include "terrain_resolve.glsl"

layout(set = 0, binding = TS_BINDING_RESOLVE_SOURCE) uniform sampler2D resolveSource;
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 stored = texelFetch(resolveSource, pixel, 0);
    // Characters, crowds and surfaces were shaded forward.
    outColor = stored.a > 0.5 ? stored : tsResolveTerrain(tsResolveViewRay(pixel), tsResolveSteps(stored.rgb));
}
