// TessPattern.h: the emulated fixed-function tessellator's GPU half, shared
// by the CPU pattern library (tessellator::PatternLibrary, which builds the
// pattern buffers and tests this file as C++) and the r2vb and streamout
// shaders (which select patterns and place their points).
//
// The emulation covers what the D3D10-era draws need: quad patches with
// fractional_odd spacing and levels 1 to 14.99, following the D3D11 rules
// (see tessellator::Tessellator). A patch's triangles split into five
// pieces whose connectivity depends only on integer point counts:
//   piece 0..3  the transition strip between outer edge `piece` and the
//               matching row of the first inner ring; key (outer points,
//               inner points along that edge);
//   piece 4     everything inside the first ring; key (inner points along
//               u, inner points along v); or the two triangles of a patch
//               whose levels are all exactly 1.
// Each key's triangles are a list of point references in a pattern buffer.
// The fractional part of every level only moves points, which the
// evaluation vertex shader does with tsEmuDomainPoint(), in the D3D11
// reference's 16.16 fixed point, so the result is the hardware's, bit for bit.
#ifndef TESSERA_TESS_PATTERN_H
#define TESSERA_TESS_PATTERN_H
#include "tessera/shaders/SharedTypes.h"

#ifdef __cplusplus
#include <bit>
#include <cmath>
#endif

/// Highest level of the emulated draws (the paper's D3D10-era maximum).
#define TS_EMU_MAX_LEVEL 14.99f
/// Pieces (tessellator commands) per patch.
#define TS_EMU_PIECES 5u
/// Outer edges have 2, 4, .. 16 points (levels 1 .. 14.99, odd spacing).
#define TS_EMU_OUTER_CLASSES 8u
/// Inner axes have 4, 6, .. 16 points (odd spacing keeps a first ring).
#define TS_EMU_INNER_CLASSES 7u
#define TS_EMU_STRIP_KEYS (TS_EMU_OUTER_CLASSES * TS_EMU_INNER_CLASSES)
#define TS_EMU_INTERIOR_KEYS (TS_EMU_INNER_CLASSES * TS_EMU_INNER_CLASSES)
#define TS_EMU_KEY_MINIMAL (TS_EMU_STRIP_KEYS + TS_EMU_INTERIOR_KEYS)
#define TS_EMU_KEY_COUNT (TS_EMU_KEY_MINIMAL + 1u)
/// The key of a piece that draws nothing (the strips of a minimal patch).
#define TS_EMU_KEY_NONE 0xffffffffu

/// Point references in the pattern buffer: type in bits 30..31.
#define TS_EMU_REF_GRID 0u   ///< inner grid point: i in bits 0..7, j in bits 8..15
#define TS_EMU_REF_OUTER 1u  ///< point k (bits 0..7) of the piece's outer edge row
#define TS_EMU_REF_RING 2u   ///< point k (bits 0..7) of the first ring's row on the piece's edge
#define TS_EMU_REF_CORNER 3u ///< domain corner: u in bit 0, v in bit 1

/// Bindings of the emulated tessellator's draw (after the terrain's).
#define TS_BINDING_EMU_KEYS 8
#define TS_BINDING_EMU_RECORDS 9

TS_NAMESPACE_BEGIN

/// The pattern library's table, one entry per key: x = first vertex in the
/// pattern buffer, y = vertex count (3 per triangle), zw unused.
struct TsEmuKeyTable {
    uvec4 pieces[TS_EMU_KEY_COUNT];
};
TS_CHECK_SIZE(TsEmuKeyTable, 1696)

TS_INLINE uint tsEmuRef(uint type, uint a, uint b) {
    return (type << 30u) | (b << 8u) | a;
}

#ifdef __cplusplus
TS_INLINE int tsFindMsb(uint value) {
    return value == 0u ? -1 : 31 - std::countl_zero(value);
}
/// 16.16 fixed point of a level in [1, 64], rounded to nearest even.
TS_INLINE uint tsToFixed(float level) {
    return static_cast<uint>(std::nearbyint(level * 65536.0f));
}
#else
int tsFindMsb(uint value) {
    return findMSB(value);
}
uint tsToFixed(float level) {
    return uint(roundEven(level * 65536.0f));
}
#endif

TS_INLINE float tsFixedToFloat(uint value) {
    return float(value >> 16u) + float(value & 0xffffu) / 65536.0f;
}

/// One axis or edge under fractional_odd spacing: the D3D11 reference's
/// per-level context.
struct TsOddSpacing {
    uint halfPoints;   ///< points on the first half, the one past the middle segment included
    uint splitPoint;   ///< beyond this index the floor level has one point fewer
    uint halfFraction; ///< fraction of half the level (16.16)
    uint invFloor;     ///< 1 / segments of the floor level (16.16)
    uint invCeil;      ///< 1 / segments of the ceiling level (16.16)
};

TS_INLINE TsOddSpacing tsOddSpacing(uint levelFxp) {
    TsOddSpacing s;
    uint halfLevel = (levelFxp + 1u) / 2u + 0x8000u;
    uint floorHalf = halfLevel & 0x7fff0000u;
    uint ceilHalf = (halfLevel & 0xffffu) != 0u ? floorHalf + 0x10000u : halfLevel;
    s.halfFraction = halfLevel - floorHalf;
    s.halfPoints = ceilHalf >> 16u;
    if (ceilHalf == floorHalf) {
        s.splitPoint = s.halfPoints + 1u;
    } else if (floorHalf == 0x10000u) {
        s.splitPoint = 0u;
    } else {
        // Ruler order: the point just past the highest power of two of the
        // floor level's half-point count splits first.
        uint floorPoints = (floorHalf >> 16u) - 1u;
        uint rest = floorPoints & ~(1u << uint(tsFindMsb(floorPoints)));
        s.splitPoint = (rest << 1u) + 1u;
    }
    uint floorSegments = ((floorHalf * 2u) >> 16u) - 1u;
    uint ceilSegments = ((ceilHalf * 2u) >> 16u) - 1u;
    s.invFloor = (0x10000u + floorSegments / 2u) / floorSegments;
    s.invCeil = (0x10000u + ceilSegments / 2u) / ceilSegments;
    return s;
}

/// Points along the edge, both ends included.
TS_INLINE uint tsOddPointCount(TsOddSpacing s) {
    return 2u * s.halfPoints;
}

/// Location (16.16) of point `index` along the edge; the second half
/// mirrors the first, so the edge reads the same from either end.
TS_INLINE uint tsOddPlace(TsOddSpacing s, uint index) {
    bool mirrored = index >= s.halfPoints;
    if (mirrored) index = 2u * s.halfPoints - index - 1u;
    uint onFloor = index > s.splitPoint ? index - 1u : index;
    uint location = onFloor * s.invFloor * (0x10000u - s.halfFraction) + index * s.invCeil * s.halfFraction;
    location = (location + 0x8000u) >> 16u;
    return mirrored ? 0x10000u - location : location;
}

/// The patch's levels as the tessellator takes them: clamped to [1, 63]
/// (NaN to 1), inner levels raised just above 1 when any level is above 1
/// (the reference's "picture frame" rule), in 16.16.
TS_INLINE void tsEmuFixedLevels(vec4 outer, vec2 inner, TS_OUT(uvec4) outerFxp, TS_OUT(uvec2) innerFxp) {
    const float threshold = 1.0f + 1.0f / 131072.0f;
    vec4 o = vec4(outer.x > 1.0f ? min(outer.x, 63.0f) : 1.0f, outer.y > 1.0f ? min(outer.y, 63.0f) : 1.0f,
                  outer.z > 1.0f ? min(outer.z, 63.0f) : 1.0f, outer.w > 1.0f ? min(outer.w, 63.0f) : 1.0f);
    bool frame = o.x > threshold || o.y > threshold || o.z > threshold || o.w > threshold || inner.x > threshold ||
                 inner.y > threshold;
    float low = frame ? 1.0f + 1.0f / 65536.0f : 1.0f;
    vec2 i = vec2(inner.x > low ? min(inner.x, 63.0f) : low, inner.y > low ? min(inner.y, 63.0f) : low);
    outerFxp = uvec4(tsToFixed(o.x), tsToFixed(o.y), tsToFixed(o.z), tsToFixed(o.w));
    innerFxp = uvec2(tsToFixed(i.x), tsToFixed(i.y));
}

TS_INLINE bool tsEmuMinimal(uvec4 outerFxp, uvec2 innerFxp) {
    return outerFxp.x == 0x10000u && outerFxp.y == 0x10000u && outerFxp.z == 0x10000u && outerFxp.w == 0x10000u &&
           innerFxp.x == 0x10000u && innerFxp.y == 0x10000u;
}

/// Points across an inner axis (at least 4, so there is a first ring).
TS_INLINE uint tsEmuInnerPoints(uint innerLevelFxp) {
    return max(tsOddPointCount(tsOddSpacing(innerLevelFxp)), 4u);
}

/// Level of component `i` (0..3) of a uvec4, without dynamic indexing.
TS_INLINE uint tsEmuPick4(uvec4 v, uint i) {
    return i == 0u ? v.x : (i == 1u ? v.y : (i == 2u ? v.z : v.w));
}

/// The inner axis whose spacing runs along outer edge `edge` (v for the
/// u = 0 and u = 1 edges).
TS_INLINE uint tsEmuAlongAxis(uint edge) {
    return (edge + 1u) & 1u;
}

/// The pattern key of piece `piece` (0..4) of a patch.
TS_INLINE uint tsEmuPieceKey(uvec4 outerFxp, uvec2 innerFxp, uint piece) {
    if (tsEmuMinimal(outerFxp, innerFxp)) return piece == 4u ? TS_EMU_KEY_MINIMAL : TS_EMU_KEY_NONE;
    uint n0 = min(tsEmuInnerPoints(innerFxp.x), 16u) / 2u - 2u;
    uint n1 = min(tsEmuInnerPoints(innerFxp.y), 16u) / 2u - 2u;
    if (piece == 4u) return TS_EMU_STRIP_KEYS + n0 * TS_EMU_INNER_CLASSES + n1;
    uint outerClass = min(tsOddPointCount(tsOddSpacing(tsEmuPick4(outerFxp, piece))), 16u) / 2u - 1u;
    return outerClass * TS_EMU_INNER_CLASSES + (tsEmuAlongAxis(piece) == 0u ? n0 : n1);
}

/// Domain point (u, v) of pattern reference `ref` in piece `piece` of a
/// patch, bit-identical to the hardware tessellator's gl_TessCoord.
TS_INLINE vec2 tsEmuDomainPoint(uint ref, uint piece, uvec4 outerFxp, uvec2 innerFxp) {
    uint type = ref >> 30u;
    uint a = ref & 0xffu;
    uint b = (ref >> 8u) & 0xffu;
    if (type == TS_EMU_REF_CORNER) return vec2(float(a & 1u), float((a >> 1u) & 1u));
    if (type == TS_EMU_REF_OUTER) {
        TsOddSpacing s = tsOddSpacing(tsEmuPick4(outerFxp, piece));
        uint last = tsOddPointCount(s) - 1u;
        // Rows run from each edge's first corner: u = 0 falling in v, v = 0
        // rising in u, u = 1 rising in v, v = 1 falling in u.
        float t = tsFixedToFloat(tsOddPlace(s, piece == 1u || piece == 2u ? a : last - a));
        if (piece == 0u) return vec2(0.0f, t);
        if (piece == 1u) return vec2(t, 0.0f);
        if (piece == 2u) return vec2(1.0f, t);
        return vec2(t, 1.0f);
    }
    uvec2 grid = uvec2(a, b);
    if (type == TS_EMU_REF_RING) {
        // Point a of the first ring's row on edge `piece`, as grid indices.
        uint along = tsEmuAlongAxis(piece);
        uint nAlong = tsEmuInnerPoints(along == 0u ? innerFxp.x : innerFxp.y);
        uint nAcross = tsEmuInnerPoints(along == 0u ? innerFxp.y : innerFxp.x);
        uint end = nAlong - 2u;
        uint alongIndex = piece == 1u || piece == 2u ? 1u + a : end - a;
        uint acrossIndex = piece < 2u ? 1u : nAcross - 2u;
        grid = along == 0u ? uvec2(alongIndex, acrossIndex) : uvec2(acrossIndex, alongIndex);
    }
    return vec2(tsFixedToFloat(tsOddPlace(tsOddSpacing(innerFxp.x), grid.x)),
                tsFixedToFloat(tsOddPlace(tsOddSpacing(innerFxp.y), grid.y)));
}

TS_NAMESPACE_END

#endif
