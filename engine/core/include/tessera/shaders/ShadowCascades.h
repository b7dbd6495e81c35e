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
    vec4 pcf;               // x: taps on a side of the receivers' percentage-closer filter (1 to 3), yzw: unused
};
TS_CHECK_SIZE(ShadowCascadeUniforms, 336)

// What a caster's depth-only draw pushes per cascade (shadow_caster.glsl):
// the cascade's matrix and what its cull per cascade reads
// (tsShadowCasterOutside).
struct ShadowCasterPush {
    mat4 viewProjection; // world to the cascade's clip space
    vec4 cull;           // x, y: the view depths (m) the cascade's slice spans (x very negative for the first),
                         // z: the cascade's clip units per metre sideways (1 / its radius),
                         // w: metres a caster's shadow reaches from its centre per metre of its radius
};
TS_CHECK_SIZE(ShadowCasterPush, 80)

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

// Whether a caster whose bounding sphere is `sphere` (world centre, radius)
// and whose centre lies `viewDepth` metres along the view axis can shadow
// nothing that reads the cascade of `viewProjection` and `cull`
// (ShadowCasterPush's): neither it nor its shadow (within cull.w radii of
// its centre) reaches the cascade's slice of the view, or it lies beside
// the cascade's square (the sun's projection is orthographic along the
// rays, so its shadow does too). The casters' cull per cascade, in their
// gl_Position or task stage, and on the CPU for drawCharacters' characters.
TS_INLINE bool tsShadowCasterOutside(vec4 sphere, float viewDepth, mat4 viewProjection, vec4 cull) {
    const float reach = sphere.w * cull.w;
    if (viewDepth < cull.x - reach || viewDepth > cull.y + reach) return true;
    const vec4 clip = viewProjection * vec4(sphere.x, sphere.y, sphere.z, 1.0f);
    const float side = 1.0f + sphere.w * cull.z;
    return abs(clip.x) > side || abs(clip.y) > side;
}

TS_NAMESPACE_END

#endif
