// R2vbCrowdLayout.h: how r2vb's crowd culling and LOD binning lays its data
// out in render targets, for its C++ passes and its shaders alike.
//
// Every pass renders one-pixel points (or, for the reduction, a full-region
// triangle) into render targets; texel `i` of a target (or region) W texels
// wide is pixel (i % W, i / W), so a row-major copy to a buffer puts texel i
// at element i (the R2VB step).
//   state      R32UI, one texel per instance id: the LOD state word
//              (CrowdLod.h). Two targets, read and written in turn.
//   pyramid    RGBA32UI histogram pyramid (HistoPyramid, Ziegler et al.
//              2006): level 0 is S x S, S a power of two, texel = instance
//              in Morton order (instance i at r2vbMortonDecode(i)), channels
//              (near, middle, far, 0) = 1 where the instance is in that
//              tier's list; level l + 1 sums 2 x 2 texels of level l up to
//              1 x 1. Even levels live in one atlas, odd ones in another
//              (r2vbPyramidOrigin), so each reduction reads one target while
//              it renders into the other.
//   listArgs   one texel per list u = tier * creatures + creature: the list
//              extraction's indirect draw (RGBA32UI) and its count (R32UI).
//   lists      RGBA32UI, one CrowdListEntry per texel; list u's region is
//              texels [u * region, u * region + maxInstances).
//   slots      RGBA32UI, texel s: near slot s's CrowdNearSlot, and the
//              skin pass's indirect draw for it.
//   commands   RGBA32UI, the emulated near tier's commands, two texels each
//              at tsCrowdNearCommandBase / 4.
//   cages      RGBA32UI, texel s * nearStride + v: slot s's compressed cage
//              vertex v.
#ifndef TESSERA_R2VB_CROWD_LAYOUT_H
#define TESSERA_R2VB_CROWD_LAYOUT_H
#include "tessera/shaders/SharedTypes.h"

/// The LOD state target a pass reads (last frame's, or this frame's).
#define R2VB_CROWD_BINDING_STATE 24
/// The pyramid's even-level and odd-level atlases (traversals read both).
#define R2VB_CROWD_BINDING_EVEN 25
#define R2VB_CROWD_BINDING_ODD 26
/// A reduction's source: the atlas holding the level below the one written.
#define R2VB_CROWD_BINDING_SOURCE 27

/// Preferred width of the row-major targets (they widen when a device's
/// largest target has too few rows).
#define R2VB_CROWD_WIDTH 256u

TS_NAMESPACE_BEGIN

/// Push constants of every r2vb crowd pass (vertex and fragment stages).
struct R2vbCrowdConstants {
    uvec4 target;    // xy: the viewport (a target or a pyramid level's region) in texels; z: level written; w: 0
    uvec4 pyramid;   // x: base side S, y: top level log2(S), z: 0, w: texels per list region in the lists target
    uvec4 ranges[4]; // creature c's instances this frame, (first, count): ranges[c / 2].xy (c even) or .zw (c odd)
};
TS_CHECK_SIZE(R2vbCrowdConstants, 96)

/// Where pyramid level `level` starts in its atlas (the even levels' for an
/// even level, else the odd levels'), for base side `side`: level 0 and 1 at
/// the origin, each later level of the same parity to the right of the
/// first, stacked downwards (they add up to less than a third of its height).
TS_INLINE uvec2 r2vbPyramidOrigin(uint level, uint side) {
    if (level < 2u) return uvec2(0u, 0u);
    const uint first = level & 1u;
    uint y = 0u;
    for (uint m = first + 2u; m < level; m += 2u) y += side >> m;
    return uvec2(side >> first, y);
}

/// The size of the atlas of parity `parity` (0: even levels) for a pyramid
/// of base side `side` and top level `top`.
TS_INLINE uvec2 r2vbPyramidAtlasSize(uint parity, uint side, uint top) {
    const uint first = max(side >> parity, 1u);
    const uint besides = parity + 2u <= top ? side >> (parity + 2u) : 0u;
    return uvec2(first + besides, first);
}

TS_NAMESPACE_END

#endif
