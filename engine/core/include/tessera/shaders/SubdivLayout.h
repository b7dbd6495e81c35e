// SubdivLayout.h: a Catmull-Clark surface as the GPU draws it (the second
// paper's base surface), one definition for the CPU that builds the arrays
// (subdiv::SubdivGpuMesh, which tests this file as C++) and for every
// backend's shaders (subdiv_eval.glsl).
//
// Tessellation domains (subdiv::SubdivDomains): quads that meet edge to
// edge, each a ptex face (a quad base face, or one of the n quad sub-faces
// of an n-gon) or, in a mesh with n-gons, one quadrant of a quad's ptex
// face. The tessellator's (u, v) maps to ptex (u, v) by tsSubdivToPtex,
// and a point's patch (OpenSubdiv's feature-adaptive B-spline patches and
// end caps, at several depths near extraordinary vertices) is found through
// its ptex face's quadtree. Corners in domain order are c0 (0,0), c1 (1,0),
// c2 (1,1), c3 (0,1); edges in Vulkan's outer-level order are e0 u = 0 (c0
// to c3), e1 v = 0 (c0 to c1), e2 u = 1 (c1 to c2), e3 v = 1 (c3 to c2),
// each parameterized by its free coordinate.
//
// Watertightness: two domains that share an edge would evaluate its points
// from different patches and control points (another depth, an end cap's
// local points), equal only in exact arithmetic. So every point on an edge
// is evaluated by one owner domain, at the owner's coordinates: the
// tessellator puts edge points at 16.16 fixed-point coordinates mirrored
// about the edge's middle, so 1 - t is exact and both domains reach the
// very same (owner, u, v) and run the very same code. Corners likewise have
// one owner each. tsSubdivCanonical() is that rule.
#ifndef TESSERA_SUBDIV_LAYOUT_H
#define TESSERA_SUBDIV_LAYOUT_H
#include "tessera/shaders/SharedTypes.h"

/// Quadtree child: a patch index with this bit, else a node index. Node p
/// is the root of ptex face p.
#define TS_SUBDIV_LEAF 0x80000000u
/// Quadtree child with no patch (only in faces that have none).
#define TS_SUBDIV_EMPTY 0xffffffffu
/// Domain flags (SubdivDomain::topology.w, bits 0..7).
#define TS_SUBDIV_DOMAIN_HOLE 1u ///< tagged as a hole: no surface, never drawn
/// SubdivDomain::topology.w >> 8 for a domain that is its whole ptex face.
#define TS_SUBDIV_WHOLE 4u
/// Patch types (PatchData.h: OpenSubdiv's Far::PatchDescriptor values).
#define TS_SUBDIV_PATCH_REGULAR 6u
#define TS_SUBDIV_PATCH_GREGORY_BASIS 9u
/// SubdivPatch::info: type in bits 0..7, extraordinary corners (bit c for
/// patch corner c, domain order) in bits 8..11.
#define TS_SUBDIV_PATCH_EV_SHIFT 8u
/// Most points a patch has (a Gregory basis end cap).
#define TS_SUBDIV_MAX_PATCH_POINTS 20u
/// Highest quadtree depth (OpenSubdiv's isolation limit).
#define TS_SUBDIV_MAX_DEPTH 10u
/// Interior of a domain (tsSubdivDomainFeature).
#define TS_SUBDIV_INTERIOR 8u

/// Bindings of a subdivision surface's data: read-only texel buffers
/// (the refined points RGBA32F, the rest RGBA32UI / RG32UI / R32UI), which
/// every era's shaders can read (D3D10/11's Buffer<>, D3D9's vertex
/// textures), so all backends run one evaluation.
#define TS_BINDING_SUBDIV_UNIFORMS 32
#define TS_BINDING_SUBDIV_POINTS 33   ///< refined points (vec4), this frame
#define TS_BINDING_SUBDIV_DOMAINS 34  ///< SubdivDomain per domain (4 texels)
#define TS_BINDING_SUBDIV_NODES 35    ///< quadtree nodes (uvec4)
#define TS_BINDING_SUBDIV_PATCHES 36  ///< SubdivPatch per patch
#define TS_BINDING_SUBDIV_INDICES 37  ///< patch point indices (uint)
#define TS_BINDING_SUBDIV_SUPPORT 38  ///< base faces' 1-rings (uint)
#define TS_BINDING_SUBDIV_TILES 39    ///< displacement tiles (texture)
#define TS_BINDING_SUBDIV_TILE_RECORDS 40
#define TS_BINDING_SUBDIV_CAGE 41     ///< this frame's base vertices (vec4)
#define TS_BINDING_SUBDIV_STENCILS 42 ///< uvec4 (first entry, count, w bits, 0) per refined point
#define TS_BINDING_SUBDIV_ENTRIES 43  ///< uvec2 (base vertex, weight bits)

TS_NAMESPACE_BEGIN

/// One tessellation domain (subdiv::SubdivDomains): a ptex face, whole or
/// one quadrant.
struct SubdivDomain {
    /// x: ptex face (its quadtree root is node x, its tile record x),
    /// y: first entry of its base face's 1-ring in the support array,
    /// z: entries, w: TS_SUBDIV_DOMAIN_* flags | quadrant << 8 (4: whole).
    uvec4 topology;
    /// Refined-point index of each corner's LOD point (domain order); the
    /// refined point's w is the corner's LOD radius.
    uvec4 corners;
    /// Per edge (outer-level order): the domain evaluating its points,
    /// domain << 3 | its edge << 1 | 1 when the edge runs the other way there.
    uvec4 edges;
    /// Per corner: the domain evaluating it, domain << 2 | its corner.
    uvec4 cornerOwners;
};
TS_CHECK_SIZE(SubdivDomain, 64)

/// One patch: info (type and extraordinary corners), first point index,
/// OpenSubdiv's two packed PatchParam words.
struct SubdivPatch {
    uvec4 data;
};
TS_CHECK_SIZE(SubdivPatch, 16)

/// Per draw: the surface's placement and the level-of-detail and shading
/// settings (a uniform block).
struct SubdivUniforms {
    mat4 model;      // object to world
    mat4 normalMatrix; // inverse transpose of model (upper 3x3 used)
    vec4 planes[6];  // world frustum planes, normals inwards (scene::Frustum's order)
    vec4 eye;        // xyz: camera position, w: pixels per metre at 1 m (viewport height * proj[1][1] / 2)
    vec4 lod;        // x: target pixels per segment, y: level cap, z: budget scale, w: fixed level (0: adaptive)
    vec4 placement;  // x: largest scale of `model`, y: displacement scale (object units), z: largest |displacement| (object units), w: unused
    uvec4 modes;     // x: TS_SUBDIV_NORMALS_*, y: 1 = mip selection, z: TS_SUBDIV_VIEW_*, w: domain count
    vec4 albedo;     // rgb: base colour, a: unused
};
TS_CHECK_SIZE(SubdivUniforms, 304)

#define TS_SUBDIV_NORMALS_APPROXIMATE 0u ///< Blinn: the Weingarten term ignored
#define TS_SUBDIV_NORMALS_ACCURATE 1u    ///< with the Weingarten term
#define TS_SUBDIV_VIEW_SHADED 0u
#define TS_SUBDIV_VIEW_PATCHES 1u ///< colour by patch type and depth
#define TS_SUBDIV_VIEW_LEVELS 2u  ///< colour by tessellation level
#define TS_SUBDIV_VIEW_MIPS 3u    ///< colour by displacement mip level

/// Point on edge `edge` (outer-level order) at its free coordinate t.
TS_INLINE vec2 tsSubdivEdgePoint(uint edge, float t) {
    if (edge == 0u) return vec2(0.0f, t);
    if (edge == 1u) return vec2(t, 0.0f);
    if (edge == 2u) return vec2(1.0f, t);
    return vec2(t, 1.0f);
}

/// Corner `corner` (domain order) as a domain point.
TS_INLINE vec2 tsSubdivCornerPoint(uint corner) {
    return vec2((corner == 1u || corner == 2u) ? 1.0f : 0.0f, corner >= 2u ? 1.0f : 0.0f);
}

/// What a domain point lies on: corner c (0..3), edge e (4 + e), or
/// TS_SUBDIV_INTERIOR. Tessellators put boundary points exactly on 0 and 1.
TS_INLINE uint tsSubdivDomainFeature(vec2 uv) {
    const bool u0 = uv.x == 0.0f;
    const bool u1 = uv.x == 1.0f;
    const bool v0 = uv.y == 0.0f;
    const bool v1 = uv.y == 1.0f;
    if ((u0 || u1) && (v0 || v1)) return u1 ? (v1 ? 2u : 1u) : (v1 ? 3u : 0u);
    if (u0) return 4u;
    if (v0) return 5u;
    if (u1) return 6u;
    if (v1) return 7u;
    return TS_SUBDIV_INTERIOR;
}

/// The domain and (u, v) that evaluate domain `index`'s point `uv` (see the
/// file comment): itself for interior points, the owner for edge and
/// corner points.
TS_INLINE void tsSubdivCanonical(SubdivDomain domain, uint index, vec2 uv, TS_OUT(uint) owner, TS_OUT(vec2) ownerUv) {
    const uint feature = tsSubdivDomainFeature(uv);
    owner = index;
    ownerUv = uv;
    if (feature < 4u) {
        const uint record = domain.cornerOwners[feature];
        owner = record >> 2u;
        ownerUv = tsSubdivCornerPoint(record & 3u);
    } else if (feature < TS_SUBDIV_INTERIOR) {
        const uint edge = feature - 4u;
        const uint record = domain.edges[edge];
        const float t = (edge == 0u || edge == 2u) ? uv.y : uv.x;
        owner = record >> 3u;
        ownerUv = tsSubdivEdgePoint((record >> 1u) & 3u, (record & 1u) != 0u ? 1.0f - t : t);
    }
}

/// Ptex (u, v) of a domain's (u, v) (`quadrant` = topology.w >> 8).
TS_INLINE vec2 tsSubdivToPtex(uint quadrant, vec2 uv) {
    if (quadrant == TS_SUBDIV_WHOLE) return uv;
    return vec2(uv.x + float(quadrant & 1u), uv.y + float(quadrant >> 1u)) * 0.5f;
}

/// Quadrant of a node holding `uv` (in the node's [0, 1]^2): bit 0 the
/// upper half in u, bit 1 in v.
TS_INLINE uint tsSubdivQuadrant(vec2 uv) {
    return (uv.x >= 0.5f ? 1u : 0u) | (uv.y >= 0.5f ? 2u : 0u);
}

/// `uv` rescaled into quadrant `quadrant`'s own [0, 1]^2 (exact: a
/// doubling and a subtraction of 0 or 1).
TS_INLINE vec2 tsSubdivIntoQuadrant(vec2 uv, uint quadrant) {
    return vec2(uv.x * 2.0f - float(quadrant & 1u), uv.y * 2.0f - float(quadrant >> 1u));
}

/// Level of detail at a corner: the projected diameter, in pixels, of the
/// sphere of `radius` (object units) around the corner's LOD point, per
/// target segment, times the budget scale; clamped to [1, cap]. Every domain
/// meeting at a corner computes the same value from the same point, so
/// shared edges get equal levels.
TS_INLINE float tsSubdivCornerLevel(vec3 world, float radius, SubdivUniforms u) {
    if (u.lod.w > 0.0f) return clamp(u.lod.w, 1.0f, u.lod.y);
    const float worldRadius = radius * u.placement.x;
    const float distance = max(length(world - vec3(u.eye.x, u.eye.y, u.eye.z)), worldRadius);
    const float pixels = 2.0f * worldRadius * u.eye.w / distance;
    return clamp(pixels / u.lod.x * u.lod.z, 1.0f, u.lod.y);
}

/// Whether a domain's surface may be in view: the sphere around its
/// support's object-space box (lo, hi), moved by `model` and grown by the
/// largest displacement, against the frustum planes.
TS_INLINE bool tsSubdivBoxVisible(vec3 lo, vec3 hi, SubdivUniforms u) {
    const vec3 centre = (lo + hi) * 0.5f;
    const vec4 world = u.model * vec4(centre.x, centre.y, centre.z, 1.0f);
    const float radius = (length(hi - lo) * 0.5f + u.placement.z) * u.placement.x;
    bool inside = true;
    for (uint i = 0u; i < 6u; ++i)
        if (dot(vec3(u.planes[i].x, u.planes[i].y, u.planes[i].z), vec3(world.x, world.y, world.z)) +
                u.planes[i].w < -radius)
            inside = false;
    return inside;
}

/// Outer and inner levels of a domain from its corner levels (domain order):
/// an edge takes the larger of its ends (symmetric, so both domains agree),
/// each inner level the larger of the two edges across it.
TS_INLINE void tsSubdivDomainLevels(vec4 corner, TS_OUT(vec4) outer, TS_OUT(vec2) inner) {
    outer = vec4(max(corner.x, corner.w), max(corner.x, corner.y), max(corner.y, corner.z), max(corner.w, corner.z));
    inner = vec2(max(outer.y, outer.w), max(outer.x, outer.z));
}

/// The corner levels interpolated bilinearly at `uv` (the paper's per-point
/// tessellation density, which selects displacement mip levels).
TS_INLINE float tsSubdivPointLevel(vec4 corner, vec2 uv) {
    const float bottom = mix(corner.x, corner.y, uv.x);
    const float top = mix(corner.w, corner.z, uv.x);
    return mix(bottom, top, uv.y);
}

TS_NAMESPACE_END

#endif
