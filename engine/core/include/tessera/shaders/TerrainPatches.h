// TerrainPatches.h: how the terrain's control mesh is indexed, for the CPU
// data model (terrain::PatchGrid) and every terrain shader alike.
//
// The control mesh is P x P square patches over the height field; patch
// (x, z) has index z * P + x and spans world [x, x+1] * patchSize.x by
// [z, z+1] * patchSize.y. Every patch edge is stored once, in a canonical
// direction (increasing X or Z), which is what makes adaptive tessellation
// crack-free: neighbours read the same stored factor for a shared edge instead
// of each computing their own (the first paper's vertex-ID swap, done by
// construction).
//   - edges along X lie on grid lines z = 0..P:  index zLine * P + x
//   - edges along Z lie on grid lines x = 0..P:  index P * (P + 1) + z * (P + 1) + xLine
// A patch's four edges in Vulkan quad outer-level order are
//   [0] u = 0 (its -X side, along Z), [1] v = 0 (its -Z side, along X),
//   [2] u = 1 (its +X side, along Z), [3] v = 1 (its +Z side, along X),
// with the evaluation domain's (u, v) running along (+X, +Z).
#ifndef TESSERA_TERRAIN_PATCHES_H
#define TESSERA_TERRAIN_PATCHES_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

TS_INLINE uint tsEdgeCount(uint patchesPerSide) {
    return 2u * patchesPerSide * (patchesPerSide + 1u);
}

TS_INLINE uint tsEdgeAlongX(uint x, uint zLine, uint patchesPerSide) {
    return zLine * patchesPerSide + x;
}

TS_INLINE uint tsEdgeAlongZ(uint xLine, uint z, uint patchesPerSide) {
    return patchesPerSide * (patchesPerSide + 1u) + z * (patchesPerSide + 1u) + xLine;
}

/// Edge `side` (0..3, outer-level order above) of patch (x, z).
TS_INLINE uint tsPatchEdge(uint x, uint z, uint side, uint patchesPerSide) {
    if (side == 0u) return tsEdgeAlongZ(x, z, patchesPerSide);
    if (side == 1u) return tsEdgeAlongX(x, z, patchesPerSide);
    if (side == 2u) return tsEdgeAlongZ(x + 1u, z, patchesPerSide);
    return tsEdgeAlongX(x, z + 1u, patchesPerSide);
}

/// Grid coordinates of the canonical first endpoint of `edge`, and in `along`
/// the unit step to its second endpoint ((1,0) along X, (0,1) along Z).
TS_INLINE vec2 tsEdgeStart(uint edge, uint patchesPerSide, TS_OUT(vec2) along) {
    uint alongX = patchesPerSide * (patchesPerSide + 1u);
    if (edge < alongX) {
        along = vec2(1.0f, 0.0f);
        return vec2(float(edge % patchesPerSide), float(edge / patchesPerSide));
    }
    uint e = edge - alongX;
    along = vec2(0.0f, 1.0f);
    return vec2(float(e % (patchesPerSide + 1u)), float(e / (patchesPerSide + 1u)));
}

TS_NAMESPACE_END

#endif
