// shadow_cascades.glsl: how much sun a point receives from the cascaded
// shadow map (docs/LOOKS.md, "Cascaded shadow maps"). The includer declares
// the ShadowCascadeUniforms block and the sampler2DArrayShadow with its own
// bindings and passes them in, so a pass reads them wherever its layout puts
// them.
#ifndef SHADOW_CASCADES_GLSL
#define SHADOW_CASCADES_GLSL
#include "tessera/shaders/ShadowCascades.h"

// The receiver's position in cascade `index`'s map: xy its texture
// coordinate, z its reference depth. Offset along the normal by a few
// texels of that cascade (which grows with the cascade, as acne would) and
// towards the sun by the constant bias, against self-shadowing acne.
// A macro over the includer's block rather than a function taking
// ShadowCascadeUniforms: a struct parameter is a copy, and a copy indexed by
// a per-pixel cascade makes a CPU rasterizer load and select all four
// matrices for every pixel instead of reading one from the block.
#define tsShadowMapCoord(u, index, world, normal) \
    tsShadowMapCoordIn((u).viewProjection[index], (u).texelSizes[index] * (u).params.z, \
                       (u).params.w / (u).depthRanges[index], world, normal)

vec3 tsShadowMapCoordIn(mat4 viewProjection, float normalOffset, float depthBias, vec3 world, vec3 normal) {
    vec4 clip = viewProjection * vec4(world + normal * normalOffset, 1.0);
    vec3 p = clip.xyz / clip.w;
    return vec3(p.xy * 0.5 + 0.5, p.z - depthBias);
}

// Sunlight kept at map coordinate `c` of layer `index` (1 lit, 0 in
// shadow): n x n taps `texel` apart of the hardware's bilinear comparison
// (n = taps: 3 filters over 4x4 texels, 2 over 3x3 for a CPU rasterizer,
// where each tap is filtered in software, 1 over 2x2).
float tsShadowTaps(sampler2DArrayShadow map, uint index, vec3 c, float texel, int taps) {
    // One tap without the loop: a CPU rasterizer runs the loop's control
    // for every pixel group.
    if (taps == 1) return texture(map, vec4(c.xy, float(index), c.z));
    // The taps centred on the receiver: offsets -1, 0, 1 texels for 3,
    // -0.5 and 0.5 for 2, 0 for 1.
    vec2 first = c.xy - vec2(0.5 * float(taps - 1) * texel);
    float lit = 0.0;
    for (int y = 0; y < taps; ++y) {
        for (int x = 0; x < taps; ++x) {
            lit += texture(map, vec4(first + vec2(x, y) * texel, float(index), c.z));
        }
    }
    return lit / float(taps * taps);
}

#endif
