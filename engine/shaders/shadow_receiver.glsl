// shadow_receiver.glsl: the cascaded shadow maps as a receiver reads them
// (docs/LOOKS.md, "Cascaded shadow maps"): the uniforms and the depth layers
// at the bindings every terrain, character and crowd layout declares
// (ShadowCascades.h), and the sunlight they keep at a point. In a frame
// without cascaded shadows the cascade count is 0 and nothing is sampled.
#ifndef SHADOW_RECEIVER_GLSL
#define SHADOW_RECEIVER_GLSL
#include "common_frame.glsl"
#include "shadow_cascades.glsl"

layout(std140, set = 0, binding = TS_BINDING_SHADOW_CASCADES) uniform ShadowCascadeBlock {
    ShadowCascadeUniforms shadowCascades;
};
layout(set = 0, binding = TS_BINDING_SHADOW_MAP) uniform sampler2DArrayShadow shadowCascadeMap;

// Sunlight the characters leave at `world` (surface normal `normal`, unit):
// 1 lit, 0 in a character's shadow.
float tsCascadedSunlight(vec3 world, vec3 normal) {
    if (shadowCascades.params.x < 0.5) return 1.0;
    // The cascade the receiver lies in; beyond the last, lit.
    float viewDepth = -(frame.view * vec4(world, 1.0)).z;
    uint count = uint(shadowCascades.params.x);
    uint index = tsShadowCascadeIndex(shadowCascades.farDistances, count, viewDepth);
    if (index >= count) return 1.0;
    return tsShadowTaps(shadowCascadeMap, index, tsShadowMapCoord(shadowCascades, index, world, normal),
                        shadowCascades.params.y, int(shadowCascades.pcf.x));
}

#endif
