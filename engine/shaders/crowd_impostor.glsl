// crowd_impostor.glsl: a card of the crowd's impostor tier (CrowdImpostor.h),
// for the vertex stage (crowd_impostor.vert: r2vb, streamout, hulldomain)
// and the mesh stage (meshshader_crowd_impostor.mesh) alike, so every
// backend draws the same card: the instance's bounding sphere seen from the
// baked view nearest the eye, as a square of side 2 r through the sphere's
// centre, facing that view (the image baked from it fits it exactly); and
// the two layers around the instance's phase. Needs TS_CROWD
// (crowd_common.glsl).
//
// The view is chosen in model space: the creature faces +Z at heading 0 and
// turns by its heading about +Y (tsCrowdWorld), so the eye's direction is
// turned back by the heading, and the card's axes forward again.
#ifndef CROWD_IMPOSTOR_GLSL
#define CROWD_IMPOSTOR_GLSL
#include "common_frame.glsl"
#include "crowd_common.glsl"
#include "tessera/shaders/CrowdImpostor.h"

// What every corner of one instance's card shares.
struct CrowdImpostorCard {
    vec3 right;    // the card's axes in world space (unit): the baked image's
    vec3 up;       // right and up
    uvec2 cell;    // the baked view shown
    vec4 bounds;   // its covered rectangle in cell coordinates (s0, t0, s1, t1)
    uvec2 layers;  // the layers of the phases around the instance's
    float weight;  // of layers.y
};

// Model-space vector `v` turned by `heading` about +Y (tsCrowdWorld's rotation).
vec3 tsCrowdImpostorToWorld(vec3 v, float heading) {
    float c = cos(heading), s = sin(heading);
    return vec3(c * v.x + s * v.z, v.y, c * v.z - s * v.x);
}

// World vector `v` turned back by `heading`: into model space.
vec3 tsCrowdImpostorToModel(vec3 v, float heading) {
    float c = cos(heading), s = sin(heading);
    return vec3(c * v.x - s * v.z, v.y, s * v.x + c * v.z);
}

CrowdImpostorCard tsCrowdImpostorCard(CrowdInstance instance) {
    float heading = instance.placement.w;
    // From the sphere's centre towards the eye, in model space.
    vec3 d = tsCrowdImpostorToModel(frame.cameraPosition.xyz - instance.sphere.xyz, heading);
    CrowdImpostorCard card;
    card.cell = tsImpostorCell(d);
    uint word = tsCrowdImpostorBoundsWord(min(instance.ids.y, TS_CROWD_MAX_CHARACTERS - 1u), card.cell);
    card.bounds = tsImpostorBoundsSt(uCrowd.impostorBounds[word >> 2u][word & 3u]);
    vec3 right, up;
    tsImpostorAxes(tsImpostorCellDirection(card.cell), right, up);
    card.right = tsCrowdImpostorToWorld(right, heading);
    card.up = tsCrowdImpostorToWorld(up, heading);
    // The instance's global clip's first layer (GpuImpostorAtlas, in the
    // GPU's clip record); a looping clip's phases wrap, others clamp.
    BakedClip clip = tsCrowdClip(instance.ids.z);
    uint layer0, layer1;
    card.weight = tsImpostorPhasePair(instance.animation.x, clip.frames.w != 0u, uint(clip.timing.w), layer0, layer1);
    card.layers = uvec2(layer0, layer1);
    return card;
}

// Corner `k` of `card`'s covered rectangle (k & 1 to the right, k >> 1
// down, from the top left): its world position and, in `uv`, where it lies
// in a layer. The rectangle is a part of the sphere's square, so the image
// lands where the whole card would have put it.
vec3 tsCrowdImpostorCorner(CrowdInstance instance, CrowdImpostorCard card, uint k, out vec2 uv) {
    vec2 st = vec2((k & 1u) != 0u ? card.bounds.z : card.bounds.x, (k >> 1u) != 0u ? card.bounds.w : card.bounds.y);
    uv = tsImpostorLayerUv(card.cell, st);
    return instance.sphere.xyz + instance.sphere.w * ((2.0 * st.x - 1.0) * card.right + (1.0 - 2.0 * st.y) * card.up);
}

// What the fragment stage (crowd_impostor.frag) needs of the card, flat:
// the two layers, the second's weight and the heading.
uvec4 tsCrowdImpostorFragmentCard(CrowdImpostorCard card, CrowdInstance instance) {
    return uvec4(card.layers, floatBitsToUint(card.weight), floatBitsToUint(instance.placement.w));
}

#endif
