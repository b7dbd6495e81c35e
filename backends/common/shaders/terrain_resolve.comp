#version 450
// The terrain resolve in compute (terrain_resolve.glsl), one invocation per
// pixel of the main target, read and written as a storage image: the
// terrain's pixels and the sky. A GPU runs compute on all of its cores;
// some (NVIDIA's H100) run fragment shaders on only a few, so there this
// costs a fraction of fullscreen passes.
#extension GL_GOOGLE_include_directive : require
#include "terrain_resolve.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = TS_BINDING_RESOLVE_TARGET, rgba8) uniform image2D target;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.viewport.xy)))) return;
    vec4 stored = imageLoad(target, pixel);
    if (stored.a > 0.5) return; // characters, crowds and surfaces were shaded forward
    uint steps = tsResolveSteps(stored.rgb);
    bool sky = steps == kTsResolveSky;
    vec3 dir = tsResolveViewRay(pixel);
    imageStore(target, pixel, sky ? tsResolveSky(dir) : tsResolveTerrain(dir, steps));
}
