// DisplacementTile.h: the tile-based displacement format of Niessner and
// Loop ("Analytic Displacement Mapping using Hardware Tessellation",
// sections 4, 5.1, 5.4 and 6.2) as a shader reads it, for the CPU reference
// (subdiv::DisplacementTiles) and the shaders alike, so both evaluate the
// displacement with the same code.
//
// Every ptex face of the base surface has a tile: the coefficients of a
// biquadratic B-spline D over the face's (u, v) in [0, 1]^2 with 2^k
// segments a side (tileSize = 2^k, 1 <= k <= TS_TILE_MAX_LOG2_SIZE),
// stored with a one-texel overlap: (tileSize + 2)^2 texels, texel (x, y)
// the coefficient centred at ((x - 0.5, y - 0.5) / tileSize), x along u and
// y along v. Overlap texels (x or y 0 or tileSize + 1) repeat the
// neighbouring tiles' coefficients, so a lookup never leaves its tile.
//
// Level l of a tile halves it l times (size tileSize >> l) down to 2 a
// side: levels 0 .. k - 1. A 1x1 level cannot exist: the 2x2 corner blocks
// averaged at extraordinary vertices (section 4.2) would overlap in its
// single texel. A tile's levels lie next to each other in one float
// texture (R32F), level 0 at the tile's origin and the others in a column
// right of it (tsTileMipOffset): (1.5 tileSize + 4) x (tileSize + 2)
// texels for tileSize >= 4, the paper's figure; 4 x 4 for tileSize 2.
//
// The record (16 bytes, one per tile or per patch; the paper's section 5.4
// struct, same field widths):
//   x: texture origin of the tile's level 0, x | y << 16
//   y: the patch's domain offset in its tile, u | v << 16, in units of its
//      domain size 2^-level (Far::PatchParam's u, v); 0 for a tile record
//   z: tileSize (bits 0-15) | k = log2(tileSize) (16-23) | domain level
//      (24-31): the patch covers [offset, offset + 1] * 2^-level of the
//      tile. The paper's record has a rotation here; OpenSubdiv 3.5 never
//      rotates a patch against its ptex face (it orders the control points
//      instead), so the slot carries the domain size
//   w: per corner (0: (0,0), 1: (1,0), 2: (1,1), 3: (0,1)) 8 bits at 8 * c:
//      bits 0-6 the corner's size difference (section 4.4): the tile's k
//      plus its scale (1 for a sub-face of a non-quad, 0 for a quad) minus
//      the finest resolution shared at the corner vertex (the smallest such
//      sum of the tiles around it). k minus the bilinear interpolant of
//      these is the finest resolution a lookup may use
//      (tsTileMaxResolution), equal on both sides of every tile edge.
//      Bit 7: the coarsest resolution is raised there, 1 at a quad's corner
//      that a sub-face also touches (its coarsest level, 2x2, matches the
//      quad's 4x4): 1 plus the interpolant is the coarsest resolution a
//      lookup may use (tsTileMinResolution), equal across edges too.
#ifndef TESSERA_DISPLACEMENT_TILE_H
#define TESSERA_DISPLACEMENT_TILE_H
#include "tessera/shaders/SharedTypes.h"

/// The smallest and largest log2(tileSize).
#define TS_TILE_MIN_LOG2_SIZE 1u
#define TS_TILE_MAX_LOG2_SIZE 12u

// The displacement texture a lookup reads: a struct over the float array on
// the CPU, a sampler2D (R32F, fetched by texel) in GLSL unless the shader
// defines TS_TILE_TEXTURE and tsTileFetch itself (a storage buffer, say).
#ifdef __cplusplus
namespace tessera::shader {
using glm::exp2;
using glm::log2;
struct TileTexture {
    const float* texels;
    uint width;
};
inline float tsTileFetch(const TileTexture& texture, uvec2 p) {
    return texture.texels[size_t(p.y) * texture.width + p.x];
}
} // namespace tessera::shader
#define TS_TILE_TEXTURE const TileTexture&
#else
#ifndef TS_TILE_TEXTURE
#define TS_TILE_TEXTURE sampler2D
float tsTileFetch(sampler2D texture, uvec2 p) {
    return texelFetch(texture, ivec2(p), 0).r;
}
#endif
#endif

TS_NAMESPACE_BEGIN

/// One tile's (or patch's) record (16 bytes, layout in the file comment).
struct TileRecord {
    uvec4 data;
};
TS_CHECK_SIZE(TileRecord, 16)

/// D and its derivatives per tile (u, v) at one point.
struct TileSample {
    vec4 value;  // x: D, y: dD/du, z: dD/dv, w: 0
    vec4 second; // x: d2D/du2, y: d2D/dudv, z: d2D/dv2, w: 0
};
TS_CHECK_SIZE(TileSample, 32)

TS_INLINE uvec2 tsTileOrigin(TileRecord r) {
    return uvec2(r.data.x & 0xffffu, r.data.x >> 16);
}
TS_INLINE uint tsTileSize(TileRecord r) {
    return r.data.z & 0xffffu;
}
TS_INLINE uint tsTileLog2Size(TileRecord r) {
    return (r.data.z >> 16) & 0xffu;
}
TS_INLINE uint tsTileDomainLevel(TileRecord r) {
    return r.data.z >> 24;
}
TS_INLINE uvec2 tsTileDomainOffset(TileRecord r) {
    return uvec2(r.data.y & 0xffffu, r.data.y >> 16);
}
/// Corner c's size difference (see the file comment).
TS_INLINE float tsTileCornerDifference(TileRecord r, uint corner) {
    return float((r.data.w >> (8u * corner)) & 0x7fu);
}
/// 1 where corner c's coarsest resolution is raised (see the file comment).
TS_INLINE float tsTileCornerRaise(TileRecord r, uint corner) {
    return float((r.data.w >> (8u * corner + 7u)) & 1u);
}

/// A patch's (s, t) in [0, 1]^2 to its tile's (u, v). Exact in float: the
/// offset and the division by a power of two lose nothing, so two patches
/// meeting at an edge reach the same tile coordinate.
TS_INLINE vec2 tsTilePatchUV(TileRecord r, vec2 st) {
    return (vec2(tsTileDomainOffset(r)) + st) / float(1u << tsTileDomainLevel(r));
}

/// Where level `level` of a tile of size 2^log2Size lies, relative to the
/// tile's origin: level 0 at (0, 0), level 1 right of it, level 2 under
/// level 1, levels 3 and on stacked right of level 2.
TS_INLINE uvec2 tsTileMipOffset(uint log2Size, uint level) {
    uint n = 1u << log2Size;
    if (level == 0u) return uvec2(0u, 0u);
    if (level == 1u) return uvec2(n + 2u, 0u);
    if (level == 2u) return uvec2(n + 2u, n / 2u + 2u);
    // Levels 3 .. l-1 above this one: sizes n >> m plus their overlaps.
    uint above = (n >> 2u) - (n >> (level - 1u)) + 2u * (level - 3u);
    return uvec2(n + 2u + n / 4u + 2u, n / 2u + 2u + above);
}

/// Texels a tile of size 2^log2Size takes in the texture, all levels.
TS_INLINE uvec2 tsTileFootprint(uint log2Size) {
    uint n = 1u << log2Size;
    return uvec2(log2Size >= 2u ? n + 2u + n / 2u + 2u : n + 2u, n + 2u);
}

/// The finest level, as a resolution (log2 of a level's size, possibly
/// fractional), a lookup at tile (u, v) may use: log2(tileSize) minus the
/// bilinear interpolant of the corner differences (section 4.4).
TS_INLINE float tsTileMaxResolution(TileRecord r, vec2 uv) {
    float d0 = tsTileCornerDifference(r, 0u), d1 = tsTileCornerDifference(r, 1u);
    float d2 = tsTileCornerDifference(r, 2u), d3 = tsTileCornerDifference(r, 3u);
    return float(tsTileLog2Size(r)) - mix(mix(d0, d1, uv.x), mix(d3, d2, uv.x), uv.y);
}

/// The coarsest resolution a lookup at tile (u, v) may use: 1 (the 2x2
/// level), up to 2 towards corners a sub-face touches.
TS_INLINE float tsTileMinResolution(TileRecord r, vec2 uv) {
    float d0 = tsTileCornerRaise(r, 0u), d1 = tsTileCornerRaise(r, 1u);
    float d2 = tsTileCornerRaise(r, 2u), d3 = tsTileCornerRaise(r, 3u);
    return 1.0f + mix(mix(d0, d1, uv.x), mix(d3, d2, uv.x), uv.y);
}

/// The resolution to sample (section 6.2): log2 of the sampling density,
/// `samplesPerTile` tessellated segments per unit of tile (u, v) (a
/// patch's tess factor times 2^domainLevel), clamped to
/// tsTileMinResolution and tsTileMaxResolution.
TS_INLINE float tsTileResolution(TileRecord r, vec2 uv, float samplesPerTile) {
    return clamp(log2(max(samplesPerTile, 1.0f)), tsTileMinResolution(r, uv), tsTileMaxResolution(r, uv));
}

/// The uniform quadratic B-spline basis at t in [0, 1]: (B0, B1, B2). B1 is
/// written as 1 - (B0 + B2) so that B(t) and B(1 - t) are exact mirrors in
/// float (the two sides of a tile edge evaluate mirrored parameters).
TS_INLINE vec3 tsQuadraticBasis(float t) {
    float s = 1.0f - t;
    float b0 = 0.5f * s * s, b2 = 0.5f * t * t;
    return vec3(b0, 1.0f - (b0 + b2), b2);
}
TS_INLINE vec3 tsQuadraticBasisDerivative(float t) {
    float d0 = t - 1.0f, d2 = t;
    return vec3(d0, -(d0 + d2), d2);
}

/// The biquadratic patch over a 3x3 block of coefficients (row j: the
/// coefficients at v index j, along u) at local (t.x, t.y) in [0, 1]^2;
/// derivatives are per tile (u, v) for a level of `n` segments a side
/// (section 5.1: the subpatch derivative times the level's size).
TS_INLINE TileSample tsTileBiquadratic(vec3 row0, vec3 row1, vec3 row2, vec2 t, float n) {
    vec3 bu = tsQuadraticBasis(t.x), bv = tsQuadraticBasis(t.y);
    vec3 du = tsQuadraticBasisDerivative(t.x), dv = tsQuadraticBasisDerivative(t.y);
    vec3 uu = vec3(1.0f, -2.0f, 1.0f);
    // Along u first, one value per row; then along v.
    vec3 rowValue = vec3(dot(bu, row0), dot(bu, row1), dot(bu, row2));
    vec3 rowDu = vec3(dot(du, row0), dot(du, row1), dot(du, row2));
    vec3 rowDuu = vec3(dot(uu, row0), dot(uu, row1), dot(uu, row2));
    TileSample s;
    s.value = vec4(dot(bv, rowValue), n * dot(bv, rowDu), n * dot(dv, rowValue), 0.0f);
    s.second = vec4(n * n * dot(bv, rowDuu), n * n * dot(dv, rowDu), n * n * dot(uu, rowValue), 0.0f);
    return s;
}

/// D at tile (u, v) from level `level` alone (0 <= level < log2Size): the
/// 3x3 coefficients of the segment holding (u, v) (the last segment holds
/// u = 1), transformed to the segment's local [0, 1]^2 (the paper's T).
TS_INLINE TileSample tsTileEvaluateLevel(TS_TILE_TEXTURE texture, TileRecord r, uint level, vec2 uv) {
    uint k = tsTileLog2Size(r);
    uint n = (1u << k) >> level;
    vec2 x = uv * float(n);
    vec2 cell = clamp(floor(x), vec2(0.0f), vec2(float(n - 1u)));
    uvec2 base = tsTileOrigin(r) + tsTileMipOffset(k, level) + uvec2(cell);
    vec3 row0 = vec3(tsTileFetch(texture, base), tsTileFetch(texture, base + uvec2(1u, 0u)),
                     tsTileFetch(texture, base + uvec2(2u, 0u)));
    vec3 row1 = vec3(tsTileFetch(texture, base + uvec2(0u, 1u)), tsTileFetch(texture, base + uvec2(1u, 1u)),
                     tsTileFetch(texture, base + uvec2(2u, 1u)));
    vec3 row2 = vec3(tsTileFetch(texture, base + uvec2(0u, 2u)), tsTileFetch(texture, base + uvec2(1u, 2u)),
                     tsTileFetch(texture, base + uvec2(2u, 2u)));
    return tsTileBiquadratic(row0, row1, row2, x - cell, float(n));
}

TS_INLINE TileSample tsTileMix(TileSample a, TileSample b, float w) {
    TileSample s;
    s.value = mix(a.value, b.value, w);
    s.second = mix(a.second, b.second, w);
    return s;
}

/// D at tile (u, v) for a sampling density (section 6.2): the two levels
/// around tsTileResolution, blended linearly (derivatives too; the blend
/// weight's own derivative is left out, as in the paper).
TS_INLINE TileSample tsTileEvaluate(TS_TILE_TEXTURE texture, TileRecord r, vec2 uv, float samplesPerTile) {
    float resolution = tsTileResolution(r, uv, samplesPerTile);
    float coarse = floor(resolution);
    uint k = tsTileLog2Size(r);
    uint coarseLevel = k - uint(coarse);
    // At resolution k exactly the weight is 0 and the finer level is level 0 itself.
    uint fineLevel = coarseLevel > 0u ? coarseLevel - 1u : 0u;
    TileSample a = tsTileEvaluateLevel(texture, r, coarseLevel, uv);
    TileSample b = tsTileEvaluateLevel(texture, r, fineLevel, uv);
    return tsTileMix(a, b, resolution - coarse);
}

/// The displaced surface f = s + N D (section 5.1): its tangents from the
/// base surface's first and second derivatives (a patch evaluation) and D,
/// dD/du, dD/dv (TileSample.value.xyz), all per the same (u, v). The
/// derivatives of the unit normal come from the Weingarten equations
/// (N_u = ((fF - eG) s_u + (eF - fE) s_v) / (EG - F^2), N_v alike, the
/// second fundamental form taken with the unit normal, so N_u is already
/// the derivative of the normalised normal). `weingarten` false drops the
/// N_u D term (Blinn's approximation, section 5.2). The displaced normal
/// is normalize(cross(fu, fv)).
TS_INLINE void tsDisplacedTangents(vec3 su, vec3 sv, vec3 suu, vec3 suv, vec3 svv, vec3 d, bool weingarten,
                                   TS_OUT(vec3) fu, TS_OUT(vec3) fv) {
    vec3 n = normalize(cross(su, sv));
    fu = su + n * d.y;
    fv = sv + n * d.z;
    if (weingarten) {
        float E = dot(su, su), F = dot(su, sv), G = dot(sv, sv);
        float e = dot(suu, n), f = dot(suv, n), g = dot(svv, n);
        float inverse = 1.0f / (E * G - F * F);
        vec3 nu = ((f * F - e * G) * su + (e * F - f * E) * sv) * inverse;
        vec3 nv = ((g * F - f * G) * su + (f * F - g * E) * sv) * inverse;
        fu = fu + nu * d.x;
        fv = fv + nv * d.x;
    }
}

TS_NAMESPACE_END

#endif
