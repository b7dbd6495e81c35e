// TessMeshPattern.h: the D3D11 fixed-function tessellator's quad patterns
// (fractional_odd spacing, levels 1 to 64) cut into pieces that each fit one
// mesh-shader workgroup, shared by the CPU library that builds the
// connectivity tables (tessellator::MeshPatternLibrary, which tests this file
// as C++) and the meshshader backend's task and mesh shaders.
//
// A patch's pattern is a sequence of row-to-row stitches, and each stitch is
// one piece: two rows of points (A and B, at most 64 each) and the triangles
// between them (at most 126):
//   pieces 0..3          the transition strip between outer edge `piece` and
//                        the first ring's row on that edge (the emulated
//                        tessellator's strips, TessPattern.h);
//   then 4 per ring pair one side of the regular stitch from ring k to ring
//                        k + 1 (k = 1 .. rings - 2), edges in order 0..3;
//   last                 the centre strip across the narrower axis;
// or a single piece, the two triangles of a patch whose levels are all 1.
// Connectivity depends only on the rows' point counts, so it is a table of
// keys (MeshPatternLibrary) with triangles as local point indices: a < rowA
// is point a of row A, otherwise point a - rowA of row B. Where the points
// lie depends on the levels' fractions, which tsMeshPiecePoint computes with
// the emulated tessellator's fixed-point placement (TessPattern.h), so every
// point is the hardware's gl_TessCoord, bit for bit.
#ifndef TESSERA_TESS_MESH_PATTERN_H
#define TESSERA_TESS_MESH_PATTERN_H
#include "tessera/shaders/TessPattern.h"

/// Highest level of the mesh-shader patterns (fractional_odd clamps to 63).
#define TS_MESH_MAX_LEVEL 64.0f
/// Outer edges have 2, 4, .. 64 points; inner axes 4, 6, .. 64.
#define TS_MESH_OUTER_CLASSES 32u
#define TS_MESH_INNER_CLASSES 31u
/// Keys: transition strips (outer class x inner class), ring sides (by the
/// outside row's points, 4 .. 64), centre strips (two diagonal rules x row
/// points 2 .. 64) and the minimal patch.
#define TS_MESH_STRIP_KEYS (TS_MESH_OUTER_CLASSES * TS_MESH_INNER_CLASSES)
#define TS_MESH_RING_KEYS 31u
#define TS_MESH_CENTRE_KEYS 32u
#define TS_MESH_KEY_RING TS_MESH_STRIP_KEYS
#define TS_MESH_KEY_CENTRE (TS_MESH_KEY_RING + TS_MESH_RING_KEYS)
#define TS_MESH_KEY_MINIMAL (TS_MESH_KEY_CENTRE + 2u * TS_MESH_CENTRE_KEYS)
#define TS_MESH_KEY_COUNT (TS_MESH_KEY_MINIMAL + 1u)
/// What one piece can need: both rows full, and the stitch's triangles.
#define TS_MESH_MAX_VERTICES 128u
#define TS_MESH_MAX_TRIANGLES 126u
/// Pieces of the densest patch: 4 strips, 4 sides of 30 ring pairs, the centre.
#define TS_MESH_MAX_PIECES 125u
/// Patches (terrain patches, surface domains) per task workgroup: one task
/// invocation each (mesh_patches.glsl; the draws' workgroup counts).
#ifndef TS_MESH_TASK_PATCHES
#define TS_MESH_TASK_PATCHES 32u
#endif

/// Bindings of the mesh-shader draws (after the terrain's or the
/// character's): the pattern tables, and the patches the task stage expands
/// (the terrain's visible patch indices, a cage's triangle indices).
#define TS_BINDING_MESH_KEYS 8
#define TS_BINDING_MESH_TRIANGLES 9
#define TS_BINDING_MESH_PATCHES 23

TS_NAMESPACE_BEGIN

/// One entry of the key table: x = first triangle in the triangle table,
/// y = triangle count, z = points of row A, w = points of row B. A triangle
/// is three local point indices, 8 bits each (a | b << 8 | c << 16), in the
/// order Tessellator emits them (Vulkan's counter-clockwise).
struct TsMeshKey {
    uvec4 entry;
};
TS_CHECK_SIZE(TsMeshKey, 16)

/// One patch's levels as the tessellator takes them, and its piece structure.
/// The spacings are computed once here: placing a point then costs no
/// division.
struct TsMeshPatch {
    uvec4 outerFxp;        ///< 16.16 outer levels (tsEmuFixedLevels)
    uvec2 innerFxp;        ///< 16.16 inner levels
    uvec2 points;          ///< inner points along u and v (4 .. 64)
    uint rings;            ///< rings of the inner grid, the first included: min(points) / 2
    uint pieceCount;       ///< pieces the patch has
    TsOddSpacing outer[4]; ///< each outer edge's spacing
    TsOddSpacing innerU;   ///< the inner axes' spacings
    TsOddSpacing innerV;
};

TS_INLINE TsMeshPatch tsMeshPatch(vec4 outer, vec2 inner) {
    TsMeshPatch p;
    tsEmuFixedLevels(outer, inner, p.outerFxp, p.innerFxp);
    for (uint e = 0u; e < 4u; ++e) p.outer[e] = tsOddSpacing(tsEmuPick4(p.outerFxp, e));
    p.innerU = tsOddSpacing(p.innerFxp.x);
    p.innerV = tsOddSpacing(p.innerFxp.y);
    p.points = uvec2(max(tsOddPointCount(p.innerU), 4u), max(tsOddPointCount(p.innerV), 4u));
    p.rings = min(p.points.x, p.points.y) / 2u;
    p.pieceCount = tsEmuMinimal(p.outerFxp, p.innerFxp) ? 1u : 4u * p.rings - 3u;
    return p;
}

TS_INLINE bool tsMeshMinimal(TsMeshPatch p) {
    return p.pieceCount == 1u;
}

/// The key of piece `piece` (0 .. pieceCount - 1).
TS_INLINE uint tsMeshPieceKey(TsMeshPatch p, uint piece) {
    if (tsMeshMinimal(p)) return TS_MESH_KEY_MINIMAL;
    if (piece < 4u) {
        uint outerPoints = tsOddPointCount(p.outer[piece]);
        uint innerPoints = tsEmuAlongAxis(piece) == 0u ? p.points.x : p.points.y;
        return (outerPoints / 2u - 1u) * TS_MESH_INNER_CLASSES + (innerPoints / 2u - 2u);
    }
    if (piece + 1u < p.pieceCount) {
        uint ring = 1u + (piece - 4u) / 4u;
        uint edge = (piece - 4u) % 4u;
        uint along = tsEmuAlongAxis(edge) == 0u ? p.points.x : p.points.y;
        return TS_MESH_KEY_RING + (along - 2u * ring) / 2u - 2u;
    }
    // The rings end in a two-row strip across the narrower axis; which
    // diagonal rule it takes depends on whether u is the wider axis.
    uint last = p.rings - 1u;
    bool wideU = p.points.x > p.points.y;
    uint length = (wideU ? p.points.x : p.points.y) - 2u * last;
    return TS_MESH_KEY_CENTRE + (wideU ? 0u : TS_MESH_CENTRE_KEYS) + length / 2u - 1u;
}

/// How many consecutive pieces of patch `p` one mesh workgroup draws: as
/// many as surely fit its TS_MESH_MAX_VERTICES and TS_MESH_MAX_TRIANGLES,
/// from bounds on any piece of the patch (a strip: the outer edge's points
/// and the first ring's row; a ring side: two rows of at most n - 2 and
/// n - 4 points; the centre: two rows of at most n), so that low levels,
/// where pieces hold a few triangles, do not spend a workgroup on each.
TS_INLINE uint tsMeshPiecesPerGroup(TsMeshPatch p) {
    uint outer = 2u;
    for (uint e = 0u; e < 4u; ++e) outer = max(outer, tsOddPointCount(p.outer[e]));
    uint inner = max(p.points.x, p.points.y);
    uint points = max(outer + inner - 2u, 2u * inner);
    uint triangles = max(outer + inner - 4u, 2u * inner - 2u);
    return max(1u, min(TS_MESH_MAX_VERTICES / points, TS_MESH_MAX_TRIANGLES / triangles));
}

/// Mesh workgroups patch `p` needs.
TS_INLINE uint tsMeshGroupCount(TsMeshPatch p) {
    uint perGroup = tsMeshPiecesPerGroup(p);
    return (p.pieceCount + perGroup - 1u) / perGroup;
}

/// Grid indices of point j of ring r's row on edge e: each row runs from its
/// edge's first corner to the next edge's (u = 0 falling in v, v = 0 rising
/// in u, u = 1 rising in v, v = 1 falling in u), as QuadPattern walks them.
TS_INLINE uvec2 tsMeshRingGrid(uvec2 points, uint r, uint e, uint j) {
    uint along = tsEmuAlongAxis(e);
    uint lastAlong = (along == 0u ? points.x : points.y) - 1u - r;
    uint lastAcross = (along == 0u ? points.y : points.x) - 1u - r;
    uint perp = e < 2u ? r : lastAcross;
    uint index = e == 1u || e == 2u ? r + j : lastAlong - j;
    return along == 0u ? uvec2(index, perp) : uvec2(perp, index);
}

/// Domain point (u, v) of point `index` of row `row` (0 = A, 1 = B) of
/// piece `piece`, bit-identical to the hardware tessellator's gl_TessCoord.
TS_INLINE vec2 tsMeshPiecePoint(TsMeshPatch p, uint piece, uint row, uint index) {
    if (tsMeshMinimal(p)) return vec2(float(index), float(row));
    uvec2 grid;
    if (piece < 4u && row == 0u) {
        // The outer edge's points, as tsEmuDomainPoint places them: rows run
        // from each edge's first corner (u = 0 falling in v, v = 0 rising in
        // u, u = 1 rising in v, v = 1 falling in u).
        TsOddSpacing s = p.outer[piece];
        uint last = tsOddPointCount(s) - 1u;
        float t = tsFixedToFloat(tsOddPlace(s, piece == 1u || piece == 2u ? index : last - index));
        if (piece == 0u) return vec2(0.0f, t);
        if (piece == 1u) return vec2(t, 0.0f);
        if (piece == 2u) return vec2(1.0f, t);
        return vec2(t, 1.0f);
    } else if (piece < 4u) {
        // The first ring's row on the strip's edge.
        grid = tsMeshRingGrid(p.points, 1u, piece, index);
    } else if (piece + 1u < p.pieceCount) {
        uint ring = 1u + (piece - 4u) / 4u;
        grid = tsMeshRingGrid(p.points, ring + row, (piece - 4u) % 4u, index);
    } else {
        // Row A is the last ring's row on edge 1 (u wider) or 0; row B the
        // opposite edge's row, reversed so both run the same way.
        uint last = p.rings - 1u;
        bool wideU = p.points.x > p.points.y;
        uint edge = (wideU ? 1u : 0u) + 2u * row;
        uint length = (wideU ? p.points.x : p.points.y) - 2u * last;
        grid = tsMeshRingGrid(p.points, last, edge, row == 0u ? index : length - 1u - index);
    }
    return vec2(tsFixedToFloat(tsOddPlace(p.innerU, grid.x)), tsFixedToFloat(tsOddPlace(p.innerV, grid.y)));
}

TS_NAMESPACE_END

#endif
