// r2vb_crowd.glsl: what r2vb's crowd passes share (R2vbCrowdLayout.h): the
// push constants, where a point lands, the Morton order of the pyramid's base,
// and the histogram pyramid's two traversals (Ziegler et al. 2006): the rank
// of an instance among a tier's elements, and the instance of a tier's k-th
// element. Define R2VB_CROWD_STATE and R2VB_CROWD_PYRAMID for the passes
// that read them; R2VB_CROWD_STATE needs crowd_common.glsl (TS_CROWD and
// TS_CROWD_TEXELS defined) included first.
#ifndef R2VB_CROWD_GLSL
#define R2VB_CROWD_GLSL
#include "tessera/shaders/CrowdInstance.h"
#include "R2vbCrowdLayout.h"

layout(push_constant) uniform R2vbCrowdPush {
    R2vbCrowdConstants pc;
};

// Clip-space position of the centre of texel `texel` of the viewport.
vec4 r2vbCrowdPixelPosition(uvec2 texel) {
    vec2 ndc = (vec2(texel) + 0.5) / vec2(pc.target.xy) * 2.0 - 1.0;
    return vec4(ndc, 0.0, 1.0);
}

// Clip-space position of texel `index` of a row-major viewport.
vec4 r2vbCrowdTexelPosition(uint index) {
    return r2vbCrowdPixelPosition(uvec2(index % pc.target.x, index / pc.target.x));
}

// A point outside the clip volume: it writes nothing.
const vec4 kR2vbCrowdNowhere = vec4(-2.0, -2.0, 0.0, 1.0);

// Creature c's instances this frame (first, count) in the sorted upload.
uvec2 r2vbCrowdRange(uint creature) {
    uvec4 r = pc.ranges[min(creature, TS_CROWD_MAX_CHARACTERS - 1u) >> 1u];
    return (creature & 1u) == 0u ? r.xy : r.zw;
}

// Morton order: bit 2k of the index is bit k of x, bit 2k + 1 bit k of y,
// so each 2 x 2 block of the base holds four consecutive instances and the
// pyramid's traversal order is the upload's order.
uint r2vbCompactBits(uint v) {
    v &= 0x55555555u;
    v = (v | (v >> 1u)) & 0x33333333u;
    v = (v | (v >> 2u)) & 0x0f0f0f0fu;
    v = (v | (v >> 4u)) & 0x00ff00ffu;
    v = (v | (v >> 8u)) & 0x0000ffffu;
    return v;
}

uint r2vbSpreadBits(uint v) {
    v &= 0x0000ffffu;
    v = (v | (v << 8u)) & 0x00ff00ffu;
    v = (v | (v << 4u)) & 0x0f0f0f0fu;
    v = (v | (v << 2u)) & 0x33333333u;
    v = (v | (v << 1u)) & 0x55555555u;
    return v;
}

uvec2 r2vbMortonDecode(uint index) {
    return uvec2(r2vbCompactBits(index), r2vbCompactBits(index >> 1u));
}

uint r2vbMortonEncode(uvec2 texel) {
    return r2vbSpreadBits(texel.x) | (r2vbSpreadBits(texel.y) << 1u);
}

#ifdef R2VB_CROWD_STATE
layout(set = 0, binding = R2VB_CROWD_BINDING_STATE) uniform usampler2D uCrowdState;

// The state word of instance id `id` in the bound state target.
uint r2vbCrowdState(uint id) {
    uint width = uint(textureSize(uCrowdState, 0).x);
    return texelFetch(uCrowdState, ivec2(id % width, id / width), 0).x;
}

// Instance i's entry in tier `tier`'s list, which holds it (its own tier's
// copy, or the fading copy in its previous tier), as
// crowd_cull.comp makes it.
CrowdListEntry r2vbCrowdEntry(uint i, uint tier, uint slot) {
    uint next = r2vbCrowdState(tsCrowdInstance(i).ids.x);
    float coverage = tsLodCoverage(next, uCrowd.lod);
    bool fadingOut = tsLodStateTier(next) != tier;
    CrowdListEntry entry;
    entry.instance = i;
    entry.slot = slot;
    entry.coverage = fadingOut ? 1.0 - coverage : coverage;
    entry.flags = (fadingOut ? 1u : 0u) | (tier << 8u);
    return entry;
}
#endif

#ifdef R2VB_CROWD_PYRAMID
layout(set = 0, binding = R2VB_CROWD_BINDING_EVEN) uniform usampler2D uPyramidEven;
layout(set = 0, binding = R2VB_CROWD_BINDING_ODD) uniform usampler2D uPyramidOdd;

// Texel `texel` of pyramid level `level`: per tier, its block's element count.
uvec4 r2vbPyramid(uint level, uvec2 texel) {
    ivec2 at = ivec2(r2vbPyramidOrigin(level, pc.pyramid.x) + texel);
    return (level & 1u) == 0u ? texelFetch(uPyramidEven, at, 0) : texelFetch(uPyramidOdd, at, 0);
}

// Elements of tier `tier` in the whole pyramid.
uint r2vbPyramidTotal(uint tier) {
    return r2vbPyramid(pc.pyramid.y, uvec2(0u))[tier];
}

// Elements of tier `tier` among instances [0, index): on the way from the
// base texel of `index` to the top, the blocks of its earlier siblings.
uint r2vbPyramidRank(uint tier, uint index) {
    uint side = pc.pyramid.x;
    if (index >= side * side) return r2vbPyramidTotal(tier);
    uvec2 p = r2vbMortonDecode(index);
    uint rank = 0u;
    for (uint level = 0u; level < pc.pyramid.y; ++level) {
        uvec2 q = p >> level;
        uvec2 parent = (q >> 1u) << 1u;
        uint quadrant = (q.x & 1u) | ((q.y & 1u) << 1u);
        for (uint k = 0u; k < quadrant; ++k) rank += r2vbPyramid(level, parent + uvec2(k & 1u, k >> 1u))[tier];
    }
    return rank;
}

// The instance of tier `tier`'s element `g` (g < the tier's total): down from
// the top, into the child whose block holds it.
uint r2vbPyramidFind(uint tier, uint g) {
    uvec2 p = uvec2(0u);
    for (int level = int(pc.pyramid.y) - 1; level >= 0; --level) {
        uvec2 base = p << 1u;
        uint k = 0u;
        for (; k < 3u; ++k) {
            uint n = r2vbPyramid(uint(level), base + uvec2(k & 1u, k >> 1u))[tier];
            if (g < n) break;
            g -= n;
        }
        p = base + uvec2(k & 1u, k >> 1u);
    }
    return r2vbMortonEncode(p);
}
#endif

#endif
