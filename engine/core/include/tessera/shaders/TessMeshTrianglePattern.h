// TessMeshTrianglePattern.h: the D3D11 fixed-function tessellator's triangle
// patterns at one uniform level (every outer and the inner level equal, as
// characters and a crowd's near tier are tessellated), fractional_odd
// spacing, levels 1 to 64, cut into pieces that each fit one mesh-shader
// workgroup. Shared by the CPU library that builds the connectivity tables
// (tessellator::MeshTrianglePatternLibrary, which tests this file as C++) and
// the meshshader backend's task and mesh shaders; the quad counterpart is
// TessMeshPattern.h, whose key entry (TsMeshKey) and limits this reuses.
//
// At level L the tessellator puts n = 2 * ceil((L + 1) / 2) points on every
// edge (4 .. 64; the single triangle of L = 1 has n = 2) and builds n / 2
// concentric rings: ring 0 is the outer edge, ring r > 0 is inset by the
// inner spacing's point r and has n - 2r points per edge, and the last ring
// (r = n/2 - 1) is three points, the centre triangle. Ring r's row on edge e
// runs from edge e's first corner to edge e + 1's (TrianglePattern walks them
// that way), so consecutive rows share a corner. A patch is then a sequence
// of row-to-row stitches, each one piece: two rows of points (A and B) and
// the triangles between them:
//   piece 3q + e   (q = 0 .. rings - 2, e = 0 .. 2) the stitch between ring
//                  q's row on edge e (A, n - 2q points) and ring q + 1's
//                  (B, two points fewer): the transition strip for q = 0,
//                  a trapezoid with mirrored diagonals for q > 0;
//   last           the centre triangle: row A is the first points of the
//                  last ring's three edges, row B is empty. The single
//                  triangle of L = 1 is this piece of a one-ring patch.
// The largest piece, level 64's transition, has 64 + 62 points and 124
// triangles, within TS_MESH_MAX_VERTICES and TS_MESH_MAX_TRIANGLES.
// Connectivity depends only on the rows' point counts, so it is a table of
// keys (MeshTrianglePatternLibrary) with triangles as local point indices:
// a < rowA is point a of row A, otherwise point a - rowA of row B. Where the
// points lie depends on the level's fraction, which tsMeshTrianglePiecePoint
// computes in the D3D11 reference's 16.16 fixed point (TessPattern.h), so
// every point is the hardware's gl_TessCoord, bit for bit.
#ifndef TESSERA_TESS_MESH_TRIANGLE_PATTERN_H
#define TESSERA_TESS_MESH_TRIANGLE_PATTERN_H
#include "tessera/shaders/TessMeshPattern.h"

/// Keys: transition strips (by points per edge, 4 .. 64), ring sides (by
/// the outside row's points, 4 .. 62) and the centre triangle.
#define TS_MESH_TRI_TRANSITION_KEYS 31u
#define TS_MESH_TRI_RING_KEYS 30u
#define TS_MESH_TRI_KEY_RING TS_MESH_TRI_TRANSITION_KEYS
#define TS_MESH_TRI_KEY_CENTRE (TS_MESH_TRI_KEY_RING + TS_MESH_TRI_RING_KEYS)
#define TS_MESH_TRI_KEY_COUNT (TS_MESH_TRI_KEY_CENTRE + 1u)
/// Pieces of the densest patch (64 points per edge): 3 per pair of its 32
/// rings, and the centre.
#define TS_MESH_TRI_MAX_PIECES 94u

/// Point classes of a uniform-level patch: 2, 4, .. 64 points an edge.
#define TS_MESH_TRI_CLASSES 32u
/// The group table's binding (MeshTrianglePatternLibrary::groups()).
#define TS_BINDING_MESH_GROUPS 29
/// Triangles one character mesh workgroup may emit: the Vulkan minimum of
/// maxMeshOutputPrimitives, twice the quads' TS_MESH_MAX_TRIANGLES, so a
/// chain of ring pieces shares more rows (MeshTrianglePatternLibrary::groups).
#define TS_MESH_TRI_GROUP_MAX_TRIANGLES 256u
/// A chain's edge value for the centre triangle.
#define TS_MESH_TRI_CHAIN_CENTRE 3u

TS_NAMESPACE_BEGIN

/// One uniform-level triangle patch and its piece structure.
struct TsMeshTrianglePatch {
    uint levelFxp;        ///< the level in 16.16, clamped to [1, 63] (tsMeshTriangleLevel)
    uint points;          ///< points per edge, corners included: 2 (level 1), 4 .. 64
    uint rings;           ///< rings, the outer edge and the centre triangle included: points / 2
    uint pieceCount;      ///< pieces (mesh workgroups) the patch needs: 3 * rings - 2
    TsOddSpacing spacing; ///< the level's point placement (every edge and the inner axis share it)
};

/// The level as the tessellator takes it when all four levels are `level`:
/// clamped to [1, 63] (NaN to 1), in 16.16. Equal levels make the
/// reference's inner-level "picture frame" rule change nothing.
TS_INLINE uint tsMeshTriangleLevel(float level) {
    return tsToFixed(level > 1.0f ? min(level, 63.0f) : 1.0f);
}

TS_INLINE TsMeshTrianglePatch tsMeshTrianglePatch(float level) {
    TsMeshTrianglePatch p;
    p.levelFxp = tsMeshTriangleLevel(level);
    p.spacing = tsOddSpacing(p.levelFxp);
    p.points = tsOddPointCount(p.spacing);
    p.rings = p.points / 2u;
    p.pieceCount = 3u * p.rings - 2u;
    return p;
}

/// The key of piece `piece` (0 .. pieceCount - 1).
TS_INLINE uint tsMeshTrianglePieceKey(TsMeshTrianglePatch p, uint piece) {
    if (piece + 1u == p.pieceCount) return TS_MESH_TRI_KEY_CENTRE;
    uint ring = piece / 3u;
    if (ring == 0u) return p.points / 2u - 2u;
    return TS_MESH_TRI_KEY_RING + (p.points - 2u * ring) / 2u - 2u;
}

/// Domain point (u, v, w) of point j of ring r's row on edge e (j = 0 ..
/// points - 2r - 1), bit-identical to the hardware tessellator's
/// gl_TessCoord.xy; w = 1 - u - v in float, as the hull/domain backend's
/// evaluation shaders take it.
TS_INLINE vec3 tsMeshTriangleRingPoint(TsMeshTrianglePatch p, uint r, uint e, uint j) {
    // A row's last point is the next edge's first: the reference adds it
    // once, from that edge, and computing it from this edge's end can differ
    // in the last bit (the inset's rounding is not symmetric).
    if (j + 1u == p.points - 2u * r) {
        e = e == 2u ? 0u : e + 1u;
        j = 0u;
    }
    // Ring r lies where the spacing's point r would be, moved in by 2/3 of
    // that distance (barycentric scaling), and takes the spacing's points
    // r .. n - 1 - r along each edge; edges 0 and 2 read it backwards. For
    // ring 0 the inset is 0 and this is the outer edge.
    uint perp = (tsOddPlace(p.spacing, r) * 0xaaaau + 0x8000u) >> 16u;
    uint shift = (perp + 1u) / 2u;
    uint place = tsOddPlace(p.spacing, e == 1u ? r + j : p.points - 1u - r - j) - shift;
    float t = tsFixedToFloat(place);
    float s = tsFixedToFloat(perp);
    vec2 uv = e == 0u ? vec2(s, t) : (e == 1u ? vec2(t, s) : vec2(t, tsFixedToFloat(0x10000u - place - perp)));
    return vec3(uv.x, uv.y, 1.0f - uv.x - uv.y);
}

/// Domain point of point `index` of row `row` (0 = A, 1 = B) of piece
/// `piece` (see the decomposition above).
TS_INLINE vec3 tsMeshTrianglePiecePoint(TsMeshTrianglePatch p, uint piece, uint row, uint index) {
    if (piece + 1u == p.pieceCount) return tsMeshTriangleRingPoint(p, p.rings - 1u, index, 0u);
    return tsMeshTriangleRingPoint(p, piece / 3u + row, piece % 3u, index);
}

TS_NAMESPACE_END

#endif
