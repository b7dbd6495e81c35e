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
vec3 tsShadowMapCoord(ShadowCascadeUniforms u, uint index, vec3 world, vec3 normal) {
    vec3 offset = world + normal * (u.texelSizes[index] * u.params.z);
    vec4 clip = u.viewProjection[index] * vec4(offset, 1.0);
    vec3 p = clip.xyz / clip.w;
    return vec3(p.xy * 0.5 + 0.5, p.z - u.params.w / u.depthRanges[index]);
}

// Sunlight kept at `world` (1 lit, 0 in shadow), at `viewDepth` metres along
// the view axis: the cascade it lies in, n x n taps a texel apart of the
// hardware's bilinear comparison (n = pcf.x: 3 filters over 4x4 texels, 2
// over 3x3 for a CPU rasterizer, where each tap is filtered in software,
// 1 over 2x2). Beyond the last cascade, and with no cascades, fully lit.
float tsCascadedShadow(ShadowCascadeUniforms u, sampler2DArrayShadow map, vec3 world, vec3 normal, float viewDepth) {
    uint count = uint(u.params.x);
    uint index = tsShadowCascadeIndex(u.farDistances, count, viewDepth);
    if (index >= count) return 1.0;
    vec3 c = tsShadowMapCoord(u, index, world, normal);
    float texel = u.params.y;
    int taps = int(u.pcf.x);
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
