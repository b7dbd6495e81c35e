// TessTrianglePattern.h: the emulated tessellator for triangles at one
// uniform level (every outer and the inner level equal), the case of a crowd's
// near tier on the r2vb and streamout backends, where the GPU picks each
// instance's level from its size on screen. Shared by the CPU pattern
// library (tessellator::TrianglePatternLibrary, which builds the patterns and
// tests this file as C++ against tessellator::Tessellator) and the emulated
// evaluation vertex shader (crowd_near_emulated.vert).
//
// With fractional_odd spacing and one level L, a triangle's connectivity
// depends only on the points per edge, n = 2 * ceil((L + 1) / 2) (4, 6, ..
// 16 for L in (1, 14.99]; the class is n / 2 - 1), or is the single
// triangle of L = 1 (class 0). The fraction of L only moves points. So a
// class's pattern is fixed: its triangles index a list of point codes, and
// the vertex shader places each code at the instance's own level with
// tsEmuTrianglePoint(), in the D3D11 reference's 16.16 fixed point, so the
// points are the hardware's gl_TessCoord, bit for bit.
//
// A point code names a point by ring, edge and index, in the order the
// reference generates them (tessellator's TrianglePattern):
//   bits 0..3  ring r: 0 the outer ring, 1 .. n/2 - 1 the inner rings, 15 a
//              corner of the minimal triangle;
//   bits 4..5  edge e (0: u = 0, 1: v = 0, 2: w = 0), each run from its first
//              corner;
//   bits 8..15 index p along the edge (the inner spacing's point index for
//              inner rings; the corner for the minimal triangle).
#ifndef TESSERA_TESS_TRIANGLE_PATTERN_H
#define TESSERA_TESS_TRIANGLE_PATTERN_H
#include "tessera/shaders/TessPattern.h"

/// Pattern classes of levels 1 .. 14.99: the minimal triangle, then 4 .. 16 points per edge.
#define TS_EMU_TRIANGLE_CLASSES 8u
/// Ring value of the minimal triangle's corners.
#define TS_EMU_TRIANGLE_CORNER 15u

TS_NAMESPACE_BEGIN

TS_INLINE uint tsEmuTriangleCode(uint ring, uint edge, uint index) {
    return ring | (edge << 4u) | (index << 8u);
}

/// The level as the tessellator takes it for a uniform triangle, in 16.16:
/// clamped to [1, TS_EMU_MAX_LEVEL] (NaN to 1).
TS_INLINE uint tsEmuTriangleLevel(float level) {
    return tsToFixed(level > 1.0f ? min(level, TS_EMU_MAX_LEVEL) : 1.0f);
}

/// The pattern class of a uniform level (16.16, from tsEmuTriangleLevel).
TS_INLINE uint tsEmuTriangleClass(uint levelFxp) {
    if (levelFxp <= 0x10000u) return 0u;
    return tsOddPointCount(tsOddSpacing(levelFxp)) / 2u - 1u;
}

/// Domain point (u, v) of point code `code` at uniform level `levelFxp`
/// (w = 1 - u - v), bit-identical to the hardware tessellator's gl_TessCoord.
TS_INLINE vec2 tsEmuTrianglePoint(uint code, uint levelFxp) {
    const uint ring = code & 15u;
    const uint edge = (code >> 4u) & 3u;
    const uint index = (code >> 8u) & 255u;
    if (ring == TS_EMU_TRIANGLE_CORNER) {
        // The minimal triangle: the first corners of edges 0, 1 and 2.
        if (index == 0u) return vec2(0.0f, 1.0f);
        if (index == 1u) return vec2(0.0f, 0.0f);
        return vec2(1.0f, 0.0f);
    }
    const TsOddSpacing s = tsOddSpacing(levelFxp);
    const uint n = tsOddPointCount(s);
    uint perp = 0u;
    uint shift = 0u;
    uint place = 0u;
    if (ring == 0u) {
        // Edges 0 and 2 read their spacing backwards.
        place = tsOddPlace(s, edge == 1u ? index : n - 1u - index);
    } else {
        // Ring r lies where the spacing's point r would be, moved in by 2/3
        // of that distance (barycentric scaling), and takes the spacing's
        // points r .. n - 1 - r along each edge.
        const uint last = n - 1u - ring;
        perp = (tsOddPlace(s, ring) * 0xaaaau + 0x8000u) >> 16u;
        shift = (perp + 1u) / 2u;
        place = tsOddPlace(s, edge == 1u ? index : last - (index - ring)) - shift;
    }
    const float t = tsFixedToFloat(place);
    const float p = tsFixedToFloat(perp);
    if (edge == 0u) return vec2(p, t);
    if (edge == 1u) return vec2(t, p);
    return vec2(t, tsFixedToFloat(0x10000u - place - perp));
}

TS_NAMESPACE_END

#endif
