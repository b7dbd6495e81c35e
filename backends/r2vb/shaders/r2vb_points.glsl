// r2vb_points.glsl: what every r2vb point pass does to write datum `index`
// into texel `index` of its render target (R2vbLayout.h), after the first
// paper's Listing 14: the vertex shader places a one-pixel point on that
// texel's centre, and the fragment shader writes the datum.
#ifndef R2VB_POINTS_GLSL
#define R2VB_POINTS_GLSL
#include "R2vbLayout.h"

layout(push_constant) uniform R2vbTarget {
    R2vbTargetConstants target;
};

// Clip-space position of the centre of texel `index`. The viewport is the
// whole target and Vulkan's NDC y runs down the rows, so no flip is needed.
vec4 r2vbTexelPosition(uint index) {
    uvec2 texel = uvec2(index % target.size.x, index / target.size.x);
    vec2 ndc = (vec2(texel) + 0.5) / vec2(target.size.xy) * 2.0 - 1.0;
    return vec4(ndc, 0.0, 1.0);
}

// Texel `index` of a target `width` texels wide, for texelFetch.
ivec2 r2vbTexel(uint index, uint width) {
    return ivec2(index % width, index / width);
}

#endif
