// MeshCaptureTestLayout.h: the buffers of the mesh-shader pattern capture
// test (tests/gpu/mesh_pattern_capture_test.cpp and shaders/mesh_capture_*)
// and the digest both sides compute, written once for C++ and GLSL so the
// CPU's digest of Tessellator's triangles and the mesh stage's digest of its
// own can differ only where the triangles do.
//
// A patch's digest is order-independent, because the mesh workgroups of a
// patch finish in any order: its triangle count, the sum of one hash of
// every triangle and the xor of a second, independent one. Each triangle is
// hashed from the 32-bit patterns of its six coordinates in canonical order
// (rotated so its smallest corner comes first, QuadPatternTriangles.h's
// canonicalTriangle), so winding counts and the starting corner does not.
// Domain points lie in [0, 1] and are multiples of 2^-16, so equal values
// have equal bits (no -0.0, no NaN).
#ifndef TESSERA_MESH_CAPTURE_TEST_LAYOUT_H
#define TESSERA_MESH_CAPTURE_TEST_LAYOUT_H
#include "tessera/shaders/SharedTypes.h"

/// The capture's own bindings, beside the pattern tables (TS_BINDING_MESH_*)
/// and the patches (TS_BINDING_MESH_PATCHES, as the backend binds them).
#define TS_CAPTURE_BINDING_RESULTS 0
#define TS_CAPTURE_BINDING_GROUPS 1
/// Patches of one triangle task workgroup at most (MS_CHARACTER_TASK_TRIANGLES).
#define TS_CAPTURE_GROUP_PATCHES 32u

TS_NAMESPACE_BEGIN

#ifdef __cplusplus
using glm::floatBitsToUint;
#endif

/// One patch's levels: quads read outer and inner.xy; uniform-level
/// triangles read outer.x (every level of the patch).
struct TsMeshCapturePatch {
    vec4 outer;
    vec4 inner;
};
TS_CHECK_SIZE(TsMeshCapturePatch, 32)

/// What the mesh stage generated for one patch (zeroed before the draw).
struct TsMeshCaptureResult {
    uint triangles;  ///< triangles emitted
    uint hashSum;    ///< sum of tsCaptureHashes(..).x over them
    uint hashXor;    ///< xor of tsCaptureHashes(..).y over them
    uint workgroups; ///< mesh workgroups (pieces) that drew the patch
};
TS_CHECK_SIZE(TsMeshCaptureResult, 16)

TS_INLINE uint tsCaptureRotl(uint x, uint r) {
    return (x << r) | (x >> (32u - r));
}

// MurmurHash3's 32-bit block step and finaliser: every input bit reaches
// every output bit, so a one-ulp move of one coordinate changes the hash.
TS_INLINE uint tsCaptureMix(uint h, uint k) {
    k *= 0xcc9e2d51u;
    k = tsCaptureRotl(k, 15u);
    k *= 0x1b873593u;
    h ^= k;
    h = tsCaptureRotl(h, 13u);
    return h * 5u + 0xe6546b64u;
}

TS_INLINE uint tsCaptureFinish(uint h) {
    h ^= 24u; // the input's length in bytes, as MurmurHash3 mixes it in
    h ^= h >> 16u;
    h *= 0x85ebca6bu;
    h ^= h >> 13u;
    h *= 0xc2b2ae35u;
    h ^= h >> 16u;
    return h;
}

TS_INLINE uint tsCaptureHash(uint seed, vec2 a, vec2 b, vec2 c) {
    uint h = seed;
    h = tsCaptureMix(h, floatBitsToUint(a.x));
    h = tsCaptureMix(h, floatBitsToUint(a.y));
    h = tsCaptureMix(h, floatBitsToUint(b.x));
    h = tsCaptureMix(h, floatBitsToUint(b.y));
    h = tsCaptureMix(h, floatBitsToUint(c.x));
    h = tsCaptureMix(h, floatBitsToUint(c.y));
    return tsCaptureFinish(h);
}

/// The two hashes of a triangle whose corners a, b, c are in canonical
/// order (two seeds: the sum and the xor would have to fail together).
TS_INLINE uvec2 tsCaptureHashes(vec2 a, vec2 b, vec2 c) {
    return uvec2(tsCaptureHash(0x9747b28cu, a, b, c), tsCaptureHash(0x5bd1e995u, a, b, c));
}

TS_NAMESPACE_END

#endif
