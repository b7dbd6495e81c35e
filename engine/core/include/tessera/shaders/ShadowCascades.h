// ShadowCascades.h: the cascaded shadow map's uniforms, filled from
// scene::ShadowCascadeFit's cascades (buildShadowCascadeUniforms) and read
// by engine/shaders/shadow_cascades.glsl, and the cascade selection both
// sides run (docs/LOOKS.md, "Cascaded shadow maps").
#ifndef TESSERA_SHADOW_CASCADES_H
#define TESSERA_SHADOW_CASCADES_H
#include "tessera/shaders/SharedTypes.h"

// The most cascades (scene::ShadowCascadeFit::kMaxCascades).
#define TS_SHADOW_MAX_CASCADES 4u

// The receivers' bindings (set 0) in every terrain, character and crowd
// layout: the ShadowCascadeUniforms block and the sampler2DArrayShadow.
#define TS_BINDING_SHADOW_CASCADES 48
#define TS_BINDING_SHADOW_MAP 49

TS_NAMESPACE_BEGIN

struct ShadowCascadeUniforms {
    mat4 viewProjection[4]; // world to each cascade's clip space (depth 0..1, no Y flip)
    vec4 farDistances;      // the view depth (m) each cascade ends at; a receiver uses the first it is within
    vec4 texelSizes;        // metres a texel of each cascade spans
    vec4 depthRanges;       // metres between each cascade's depth 0 and 1
    vec4 params;            // x: cascade count (0: no cascaded shadows), y: 1 / map size (texels),
                            // z: normal offset (texels), w: constant depth bias (m)
};
TS_CHECK_SIZE(ShadowCascadeUniforms, 320)

// The cascade a receiver at `viewDepth` metres along the view axis reads:
// the first whose far distance it is within, or `count` beyond the last
// (no shadow there). scene::ShadowCascadeFit::cascadeIndex is its twin.
TS_INLINE uint tsShadowCascadeIndex(vec4 farDistances, uint count, float viewDepth) {
    uint index = count;
    for (uint i = 0u; i < count; ++i) {
        if (index == count && viewDepth <= farDistances[i]) index = i;
    }
    return index;
}

TS_NAMESPACE_END

#endif
