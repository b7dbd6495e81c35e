// CompressedVertex.h: the paper's 128-bit animated vertex (Figure 10,
// Listings 11 and 12), written once for the C++ reference and the shaders.
// The first pass of the two-pass method skins each cage vertex and packs it
// with tsPackVertex(); the tessellation pass fetches one uvec4 per
// superprimitive vertex and decodes it with tsUnpackVertex().
//
//   x = X16 << 16 | Y16                position: fixed point in the box
//   y = Z16 << 16 | Ttheta8 << 8 | Tphi8  tangent: quantised spherical
//   z = Nx10 << 22 | Ny11 << 11 | Nz11  normal: signed normalised, DEC3N-like
//   w = U16 << 16 | V16                uv: fixed point in the uv range
//
// Departures from the listings, and why:
//   - uv is fixed point in a per-character range (uvMin, uvMax) rather than
//     [0, 1], so models whose UVs leave [0, 1] (tiling, UDIM-like charts)
//     still work; with the range [0, 1] it is the paper's encoding.
//   - The normal's fields are two's-complement SNORM (value * (2^(n-1) - 1)),
//     as D3D's DEC3N, where Listing 11 biases them to unsigned: zero and +-1
//     are exact, so axis-aligned normals survive unchanged, for a step of
//     1/511 (10 bits) instead of 2/1023.
//   - Listing 11's bugs are fixed: vSphericalNorm was undefined (it is the
//     spherical pair), statements missed semicolons, atan2 ran before the
//     s == 0 check (atan(0, 0) is undefined in GLSL), and acos(z) of an
//     unclamped z could be NaN; theta is now atan(s, z), which needs no
//     clamp. No division by s is needed: atan(x, y) = atan(x/s, y/s).
//   - Rounding is floor(v * max + 0.5), identical in C++ and every GLSL
//     implementation (round() may go either way at .5 in GLSL).
//
// The unpacked normal and tangent are normalised. The tangent is not exactly
// perpendicular to the normal after quantisation: shaders re-orthogonalise
// it (Gram-Schmidt against the normal) before building the frame. As in the
// paper the bitangent is not stored: it is recomputed as cross(normal,
// tangent). Its sign (glTF's tangent.w, -1 on mirrored UV charts) is not
// stored either; skinning never changes it, so a renderer that needs it
// reads it from the bind-pose cage data, or assumes +1.
#ifndef TESSERA_COMPRESSED_VERTEX_H
#define TESSERA_COMPRESSED_VERTEX_H
#include "tessera/shaders/SharedTypes.h"

#ifndef TS_PI
#define TS_PI 3.14159265358979f
#endif

TS_NAMESPACE_BEGIN

/// Largest code of an nBits-wide unsigned field, as a float (2^nBits - 1).
TS_INLINE float tsQuantMax(uint nBits) {
    return float((1u << nBits) - 1u);
}

/// Quantises v in [0, 1] (clamped) to nBits, rounding half up.
TS_INLINE uint tsQuantize(float v, uint nBits) {
    return uint(floor(clamp(v, 0.0f, 1.0f) * tsQuantMax(nBits) + 0.5f));
}

/// Inverse of tsQuantize: a code back to [0, 1].
TS_INLINE float tsDequantize(uint n, uint nBits) {
    return float(n) / tsQuantMax(nBits);
}

/// v's position in [lo, hi] as a fraction, clamped; 0 for an empty range
/// (a flat box axis), so no division by zero.
TS_INLINE float tsUnitInRange(float v, float lo, float hi) {
    return hi > lo ? clamp((v - lo) / (hi - lo), 0.0f, 1.0f) : 0.0f;
}

/// v in [-1, 1] (clamped) as an nBits-wide two's-complement SNORM field.
TS_INLINE uint tsQuantizeSnorm(float v, uint nBits) {
    float m = float((1u << (nBits - 1u)) - 1u);
    int q = int(floor(clamp(v, -1.0f, 1.0f) * m + 0.5f));
    return uint(q) & ((1u << nBits) - 1u);
}

/// The SNORM field of `bits` bits whose top bit is bit `top` of `word`, back
/// to [-1, 1]. Shifting the field to the top and back sign-extends it.
TS_INLINE float tsDequantizeSnorm(uint word, uint top, uint bits) {
    int q = int(word << (31u - top)) >> (32u - bits);
    float m = float((1u << (bits - 1u)) - 1u);
    return max(float(q) / m, -1.0f);
}

/// Unit vector (any non-zero vector; zero reads as +z) to spherical
/// coordinates: x = theta in [0, pi] from +z, y = phi in [-pi, pi] with
/// sin(phi) ~ x and cos(phi) ~ y (the paper's convention).
TS_INLINE vec2 tsCartesianToSpherical(vec3 v) {
    float len = length(v);
    vec3 u = len > 0.0f ? v / len : vec3(0.0f, 0.0f, 1.0f);
    float s = sqrt(u.x * u.x + u.y * u.y);
    // theta = atan(s, z) rather than the listing's acos(z): equal for unit
    // vectors, well conditioned at the poles where acos is not, and it keeps
    // GLSL in step with C++ (lavapipe's acos put 0.6% of theta codes one off
    // the C++ ones, its atan none).
    float theta = atan(s, u.z);
    // At the poles phi is arbitrary; atan(0, 0) is undefined in GLSL.
    float phi = s > 0.0f ? atan(u.x, u.y) : 0.0f;
    return vec2(theta, phi);
}

/// Spherical (theta, phi) back to a unit vector.
TS_INLINE vec3 tsSphericalToCartesian(vec2 sph) {
    float sinTheta = sin(sph.x);
    return vec3(sin(sph.y) * sinTheta, cos(sph.y) * sinTheta, cos(sph.x));
}

/// A direction as two nBits quantised spherical coordinates (theta, phi).
TS_INLINE uvec2 tsCompressVectorQSC(vec3 v, uint nBits) {
    vec2 sph = tsCartesianToSpherical(v);
    return uvec2(tsQuantize(sph.x / TS_PI, nBits), tsQuantize((sph.y + TS_PI) / (2.0f * TS_PI), nBits));
}

/// Inverse of tsCompressVectorQSC; unit length.
TS_INLINE vec3 tsDecompressVectorQSC(uvec2 q, uint nBits) {
    vec2 sph = vec2(tsDequantize(q.x, nBits) * TS_PI, tsDequantize(q.y, nBits) * (2.0f * TS_PI) - TS_PI);
    return tsSphericalToCartesian(sph);
}

/// A unit normal as the 10/11/11 SNORM word (zero reads as +z).
TS_INLINE uint tsPackNormal(vec3 n) {
    float len = length(n);
    vec3 u = len > 0.0f ? n / len : vec3(0.0f, 0.0f, 1.0f);
    return (tsQuantizeSnorm(u.x, 10u) << 22u) | (tsQuantizeSnorm(u.y, 11u) << 11u) | tsQuantizeSnorm(u.z, 11u);
}

/// Inverse of tsPackNormal, normalised.
TS_INLINE vec3 tsUnpackNormal(uint word) {
    vec3 n =
        vec3(tsDequantizeSnorm(word, 31u, 10u), tsDequantizeSnorm(word, 21u, 11u), tsDequantizeSnorm(word, 10u, 11u));
    return normalize(n);
}

/// Packs one animated vertex (model space) into the Figure 10 layout.
/// Positions outside [boxMin, boxMax] and uvs outside [uvMin, uvMax] clamp.
TS_INLINE uvec4 tsPackVertex(vec3 position, vec3 normal, vec3 tangent, vec2 uv, vec3 boxMin, vec3 boxMax, vec2 uvMin,
                             vec2 uvMax) {
    uint px = tsQuantize(tsUnitInRange(position.x, boxMin.x, boxMax.x), 16u);
    uint py = tsQuantize(tsUnitInRange(position.y, boxMin.y, boxMax.y), 16u);
    uint pz = tsQuantize(tsUnitInRange(position.z, boxMin.z, boxMax.z), 16u);
    uvec2 t = tsCompressVectorQSC(tangent, 8u);
    uint u = tsQuantize(tsUnitInRange(uv.x, uvMin.x, uvMax.x), 16u);
    uint v = tsQuantize(tsUnitInRange(uv.y, uvMin.y, uvMax.y), 16u);
    return uvec4((px << 16u) | py, (pz << 16u) | (t.x << 8u) | t.y, tsPackNormal(normal), (u << 16u) | v);
}

/// The position alone (what a depth-only or shadow pass needs).
TS_INLINE vec3 tsUnpackPosition(uvec4 pv, vec3 boxMin, vec3 boxMax) {
    vec3 f = vec3(tsDequantize(pv.x >> 16u, 16u), tsDequantize(pv.x & 0xffffu, 16u), tsDequantize(pv.y >> 16u, 16u));
    return mix(boxMin, boxMax, f);
}

/// The tangent alone: unit length, not yet orthogonal to the normal.
TS_INLINE vec3 tsUnpackTangent(uvec4 pv) {
    return normalize(tsDecompressVectorQSC(uvec2((pv.y >> 8u) & 0xffu, pv.y & 0xffu), 8u));
}

/// The uv alone.
TS_INLINE vec2 tsUnpackUV(uvec4 pv, vec2 uvMin, vec2 uvMax) {
    vec2 f = vec2(tsDequantize(pv.w >> 16u, 16u), tsDequantize(pv.w & 0xffffu, 16u));
    return mix(uvMin, uvMax, f);
}

/// Unpacks a vertex packed with the same box and uv range. Normal and
/// tangent are unit length; see the file comment for the tangent frame.
TS_INLINE void tsUnpackVertex(uvec4 pv, vec3 boxMin, vec3 boxMax, vec2 uvMin, vec2 uvMax, TS_OUT(vec3) position,
                              TS_OUT(vec3) normal, TS_OUT(vec3) tangent, TS_OUT(vec2) uv) {
    position = tsUnpackPosition(pv, boxMin, boxMax);
    normal = tsUnpackNormal(pv.z);
    tangent = tsUnpackTangent(pv);
    uv = tsUnpackUV(pv, uvMin, uvMax);
}

TS_NAMESPACE_END

#endif
