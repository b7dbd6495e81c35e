// subdiv_eval.glsl: the second paper's displaced Catmull-Clark surface at
// a tessellator's domain point, shared by hulldomain's evaluation shader
// and the emulated backends' evaluation vertex shader, so all three place
// the same vertices; and its per-pixel normal, for the fragment shader.
//
// At a domain point (SubdivLayout.h):
//   1. the owner rule (tsSubdivCanonical) picks the domain and (u, v) that
//      evaluate it, so shared edges and corners come out bit-identical;
//   2. the owner's ptex face's quadtree gives the patch, OpenSubdiv's basis
//      (subdiv_patch.glsl) the limit point s and its derivatives;
//   3. the displacement D (DisplacementTile.h) at the level of detail the
//      owner's corner levels give there (section 6: per-vertex levels,
//      interpolated, select and blend two mip levels) moves the point along
//      the unit normal: f = s + N D.
// The tangent frame a fragment shades with (s_u, s_v, N, and N_u, N_v for
// the Weingarten term) is the point's own domain's, so it interpolates
// consistently across the triangle; at shared points it differs from the
// owner's only by rounding and the end caps' approximation.
#ifndef SUBDIV_EVAL_GLSL
#define SUBDIV_EVAL_GLSL
#include "tessera/shaders/SubdivLayout.h"
#include "tessera/shaders/DisplacementTile.h"
#include "subdiv_patch.glsl"

layout(std140, set = 0, binding = TS_BINDING_SUBDIV_UNIFORMS) uniform SubdivBlock {
    SubdivUniforms subdiv;
};
layout(set = 0, binding = TS_BINDING_SUBDIV_POINTS) uniform samplerBuffer subdivPoints;
layout(set = 0, binding = TS_BINDING_SUBDIV_DOMAINS) uniform usamplerBuffer subdivDomains;
layout(set = 0, binding = TS_BINDING_SUBDIV_NODES) uniform usamplerBuffer subdivNodes;
layout(set = 0, binding = TS_BINDING_SUBDIV_PATCHES) uniform usamplerBuffer subdivPatches;
layout(set = 0, binding = TS_BINDING_SUBDIV_INDICES) uniform usamplerBuffer subdivIndices;
layout(set = 0, binding = TS_BINDING_SUBDIV_TILES) uniform sampler2D subdivTiles;
layout(set = 0, binding = TS_BINDING_SUBDIV_TILE_RECORDS) uniform usamplerBuffer subdivTileRecords;

SubdivDomain tsSubdivLoadDomain(uint index) {
    int base = int(index) * 4;
    SubdivDomain d;
    d.topology = texelFetch(subdivDomains, base);
    d.corners = texelFetch(subdivDomains, base + 1);
    d.edges = texelFetch(subdivDomains, base + 2);
    d.cornerOwners = texelFetch(subdivDomains, base + 3);
    return d;
}

uint tsSubdivQuadrantOf(SubdivDomain d) {
    return d.topology.w >> 8u;
}

// The patch holding ptex (u, v) of a ptex face (TS_SUBDIV_EMPTY if none).
uint tsSubdivFindPatch(uint ptexFace, vec2 uv) {
    uint node = ptexFace;
    for (uint level = 0u; level <= TS_SUBDIV_MAX_DEPTH; ++level) {
        uint quadrant = tsSubdivQuadrant(uv);
        uint child = texelFetch(subdivNodes, int(node))[quadrant];
        if (child == TS_SUBDIV_EMPTY) return child;
        if ((child & TS_SUBDIV_LEAF) != 0u) return child & ~TS_SUBDIV_LEAF;
        uv = tsSubdivIntoQuadrant(uv, quadrant);
        node = child;
    }
    return TS_SUBDIV_EMPTY;
}

// A limit point with derivatives per ptex (u, v), in object space.
struct TsSubdivLimit {
    vec3 p, du, dv, duu, duv, dvv;
    float evBlend; // 1 at an end cap's extraordinary corner, 0 at its others
};

TsSubdivLimit tsSubdivEvaluateLimit(uint ptexFace, vec2 ptexUv, bool second) {
    TsSubdivLimit s;
    s.p = s.du = s.dv = s.duu = s.duv = s.dvv = vec3(0.0);
    s.evBlend = 0.0;
    uint patchIndex = tsSubdivFindPatch(ptexFace, clamp(ptexUv, 0.0, 1.0));
    if (patchIndex == TS_SUBDIV_EMPTY) return s;
    uvec4 patch_ = texelFetch(subdivPatches, int(patchIndex));
    uvec3 param = uvec3(patch_.z, patch_.w, 0u);
    vec2 st = clamp(tsSubdivPatchCoord(param, ptexUv), 0.0, 1.0);
    float wP[20], wDu[20], wDv[20], wDuu[20], wDuv[20], wDvv[20];
    int n = tsSubdivBasis2(patch_.x & 0xffu, param, st, wP, wDu, wDv, wDuu, wDuv, wDvv);
    for (int k = 0; k < n; ++k) {
        vec3 c = texelFetch(subdivPoints, int(texelFetch(subdivIndices, int(patch_.y) + k).r)).xyz;
        s.p += wP[k] * c;
        s.du += wDu[k] * c;
        s.dv += wDv[k] * c;
        if (second) {
            s.duu += wDuu[k] * c;
            s.duv += wDuv[k] * c;
            s.dvv += wDvv[k] * c;
        }
    }
    // The paper's blend at extraordinary vertices (section 5.4): weight 1
    // at the end cap's extraordinary corner, bilinear to 0 at the others.
    uint ev = patch_.x >> TS_SUBDIV_PATCH_EV_SHIFT;
    vec4 corner = vec4((1.0 - st.x) * (1.0 - st.y), st.x * (1.0 - st.y), st.x * st.y, (1.0 - st.x) * st.y);
    for (uint c = 0u; c < 4u; ++c)
        if ((ev & (1u << c)) != 0u) s.evBlend = max(s.evBlend, corner[c]);
    return s;
}

// The unit normal of a limit point (outward for counter-clockwise faces);
// (0, 0, 0) where the tangents are parallel.
vec3 tsSubdivNormal(vec3 du, vec3 dv) {
    vec3 n = cross(du, dv);
    float len2 = dot(n, n);
    return len2 > 1e-30 ? n * inversesqrt(len2) : vec3(0.0);
}

// The unit normal's derivatives (the Weingarten term's ingredients): the
// derivative of N* / |N*| with N* = s_u x s_v.
void tsSubdivNormalDerivatives(TsSubdivLimit s, vec3 n, out vec3 nu, out vec3 nv) {
    vec3 raw = cross(s.du, s.dv);
    float len = length(raw);
    nu = nv = vec3(0.0);
    if (len <= 1e-30) return;
    vec3 rawU = cross(s.duu, s.dv) + cross(s.du, s.duv);
    vec3 rawV = cross(s.duv, s.dv) + cross(s.du, s.dvv);
    nu = (rawU - n * dot(rawU, n)) / len;
    nv = (rawV - n * dot(rawV, n)) / len;
}

// Corner levels of a domain (domain order), from its LOD points.
vec4 tsSubdivCornerLevels(SubdivDomain d) {
    vec4 levels;
    for (uint c = 0u; c < 4u; ++c) {
        vec4 point = texelFetch(subdivPoints, int(d.corners[c]));
        vec3 world = (subdiv.model * vec4(point.xyz, 1.0)).xyz;
        levels[c] = tsSubdivCornerLevel(world, point.w, subdiv);
    }
    return levels;
}

TileRecord tsSubdivTileRecord(uint ptexFace) {
    TileRecord r;
    r.data = texelFetch(subdivTileRecords, int(ptexFace));
    return r;
}

// Samples per unit of ptex (u, v) for a domain level: a quadrant is half
// its ptex face.
float tsSubdivTileDensity(SubdivDomain d, float level) {
    return tsSubdivQuadrantOf(d) == TS_SUBDIV_WHOLE ? level : 2.0 * level;
}

// D (object units) and its ptex derivatives at a domain point, at the
// domain's interpolated level (or the finest level the tile allows when mip
// selection is off).
vec3 tsSubdivDisplacement(SubdivDomain d, vec2 ptexUv, float level) {
    if (subdiv.placement.y == 0.0) return vec3(0.0);
    TileRecord r = tsSubdivTileRecord(d.topology.x);
    float density = subdiv.modes.y != 0u ? tsSubdivTileDensity(d, level) : 65536.0;
    TileSample s = tsTileEvaluate(subdivTiles, r, clamp(ptexUv, 0.0, 1.0), density);
    return s.value.xyz * subdiv.placement.y;
}

// What an evaluation stage hands the fragment shader.
struct TsSubdivVertex {
    vec3 position;   // displaced, object space
    vec3 du, dv;     // limit tangents per ptex (u, v), object space
    vec3 nu, nv;     // the unit normal's derivatives (accurate normals only)
    vec2 ptexUv;     // of the evaluating domain
    float level;     // interpolated corner level (selects the mip)
    float evBlend;   // the extraordinary-vertex blend weight
};

// Everything at one domain point, evaluated by that domain.
TsSubdivVertex tsSubdivEvaluateAt(uint domainIndex, vec2 uv) {
    SubdivDomain d = tsSubdivLoadDomain(domainIndex);
    bool accurate = subdiv.modes.x == TS_SUBDIV_NORMALS_ACCURATE;
    TsSubdivVertex v;
    v.ptexUv = tsSubdivToPtex(tsSubdivQuadrantOf(d), uv);
    TsSubdivLimit s = tsSubdivEvaluateLimit(d.topology.x, v.ptexUv, accurate);
    v.du = s.du;
    v.dv = s.dv;
    v.evBlend = s.evBlend;
    v.level = tsSubdivPointLevel(tsSubdivCornerLevels(d), uv);
    vec3 n = tsSubdivNormal(s.du, s.dv);
    v.nu = v.nv = vec3(0.0);
    if (accurate) tsSubdivNormalDerivatives(s, n, v.nu, v.nv);
    v.position = s.p + n * tsSubdivDisplacement(d, v.ptexUv, v.level).x;
    return v;
}

// Evaluates domain `domainIndex` at its domain point `uv` (gl_TessCoord or
// an emulated tessellator's point). The position always comes from the one
// call at (owner, owner's uv), so every domain sharing the point runs the
// same instructions on the same inputs (no context-dependent contraction
// can tell them apart); a point some other domain owns takes its shading
// frame from a second evaluation by its own domain.
TsSubdivVertex tsSubdivEvaluate(uint domainIndex, vec2 uv) {
    SubdivDomain d = tsSubdivLoadDomain(domainIndex);
    uint owner;
    vec2 ownerUv;
    tsSubdivCanonical(d, domainIndex, uv, owner, ownerUv);
    TsSubdivVertex v = tsSubdivEvaluateAt(owner, ownerUv);
    if (owner != domainIndex || ownerUv != uv) {
        vec3 position = v.position;
        v = tsSubdivEvaluateAt(domainIndex, uv);
        v.position = position;
    }
    return v;
}

// The displaced surface's unit normal at a fragment (section 5.3: per
// pixel, from D's derivatives there), in object space: f_u = s_u + N D_u
// (+ N_u D with the Weingarten term), blended to the limit normal towards
// an end cap's extraordinary corner.
vec3 tsSubdivShadingNormal(uint domainIndex, TsSubdivVertex v) {
    vec3 n = tsSubdivNormal(v.du, v.dv);
    if (subdiv.placement.y == 0.0) return n;
    SubdivDomain d = tsSubdivLoadDomain(domainIndex);
    vec3 disp = tsSubdivDisplacement(d, v.ptexUv, v.level);
    vec3 fu = v.du + n * disp.y;
    vec3 fv = v.dv + n * disp.z;
    if (subdiv.modes.x == TS_SUBDIV_NORMALS_ACCURATE) {
        fu += v.nu * disp.x;
        fv += v.nv * disp.x;
    }
    vec3 nf = tsSubdivNormal(fu, fv);
    if (dot(nf, nf) == 0.0) return n;
    return normalize(mix(nf, n, clamp(v.evBlend, 0.0, 1.0)));
}

#endif
