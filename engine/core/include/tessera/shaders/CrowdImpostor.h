// CrowdImpostor.h: the crowd's impostor tier (TS_LOD_IMPOSTOR), one
// definition for the baker (character::bakeImpostors, on the CPU at content
// build or load time) and for every backend's impostor draw, so the views a
// creature was baked from and the cards that show them agree exactly.
//
// An impostor atlas holds, per global baked clip and animation phase, one
// layer of TS_IMPOSTOR_VIEWS x TS_IMPOSTOR_VIEWS cells; a cell is the
// creature seen from one direction of the upper hemisphere (hemi-octahedral
// layout: a direction's cell is where tsImpostorEncode puts it), drawn
// orthographically into a square of side 2 R centred on the creature's
// bounding sphere (the instance sphere's centre on the vertical axis and its
// radius, in model space: docs/CROWD.md 6.9). Each texel stores the base
// colour and coverage, and the model-space normal, so a card is lit by the
// same sun and sky as the meshes.
//
// Model space: +Y up, the creature faces +Z (heading 0). A direction points
// from the creature towards the eye.
#ifndef TESSERA_CROWD_IMPOSTOR_H
#define TESSERA_CROWD_IMPOSTOR_H
#include "tessera/shaders/SharedTypes.h"

/// Cells a side of a layer (views: TS_IMPOSTOR_VIEWS squared).
#define TS_IMPOSTOR_VIEWS 8u
/// Texels a side of a cell at mip 0 (a layer is VIEWS * CELL texels a side).
#define TS_IMPOSTOR_CELL 32u
/// Animation phases baked per clip, evenly over its cycle (a looping clip:
/// phase k at k / PHASES; any other: k / (PHASES - 1)).
#define TS_IMPOSTOR_PHASES 8u
/// Mip levels baked (cells of 32, 16, 8 and 4 texels).
#define TS_IMPOSTOR_MIPS 4u
/// Texels left empty round the creature's square in every cell, so a
/// filtered lookup near a cell's edge never reads its neighbour.
#define TS_IMPOSTOR_BORDER 1u

TS_NAMESPACE_BEGIN

/// The hemi-octahedral coordinates in [0, 1]^2 of direction `d` (any
/// length; one below the horizon is taken at the horizon).
TS_INLINE vec2 tsImpostorEncode(vec3 d) {
    const vec3 up = vec3(d.x, max(d.y, 0.0f), d.z);
    const float a = abs(up.x) + abs(up.y) + abs(up.z);
    const float px = a > 0.0f ? up.x / a : 0.0f, pz = a > 0.0f ? up.z / a : 0.0f;
    return vec2(0.5f * (px + pz) + 0.5f, 0.5f * (px - pz) + 0.5f);
}

/// The unit direction at hemi-octahedral coordinates `uv` (inverse of
/// tsImpostorEncode).
TS_INLINE vec3 tsImpostorDecode(vec2 uv) {
    const float u = 2.0f * uv.x - 1.0f, v = 2.0f * uv.y - 1.0f;
    const float px = 0.5f * (u + v), pz = 0.5f * (u - v);
    return normalize(vec3(px, max(1.0f - abs(px) - abs(pz), 0.0f), pz));
}

/// The cell (column, row) whose view is nearest direction `d`.
TS_INLINE uvec2 tsImpostorCell(vec3 d) {
    const vec2 uv = tsImpostorEncode(d);
    const float n = float(TS_IMPOSTOR_VIEWS);
    return uvec2(uint(clamp(floor(uv.x * n), 0.0f, n - 1.0f)), uint(clamp(floor(uv.y * n), 0.0f, n - 1.0f)));
}

/// The direction cell `cell` was baked from (its centre's).
TS_INLINE vec3 tsImpostorCellDirection(uvec2 cell) {
    const float n = float(TS_IMPOSTOR_VIEWS);
    return tsImpostorDecode(vec2((float(cell.x) + 0.5f) / n, (float(cell.y) + 0.5f) / n));
}

/// The card's axes for view direction `d` (unit): `right` and `up` span
/// the image, right = cross(+Y, d) normalised (+X straight from above).
TS_INLINE void tsImpostorAxes(vec3 d, TS_OUT(vec3) right, TS_OUT(vec3) up) {
    const vec3 r = cross(vec3(0.0f, 1.0f, 0.0f), d);
    const float l = length(r);
    right = l > 1e-4f ? r / l : vec3(1.0f, 0.0f, 0.0f);
    up = cross(d, right);
}

/// Where a point `p` (model space) falls in a cell baked from direction `d`
/// round the sphere (`centre`, `radius`): (s, t) in [0, 1]^2, s to the right,
/// t down (image rows from the top), and its depth towards the eye.
TS_INLINE vec3 tsImpostorProject(vec3 p, vec3 d, vec3 centre, float radius) {
    vec3 right, up;
    tsImpostorAxes(d, right, up);
    const vec3 q = p - centre;
    return vec3(0.5f + dot(q, right) / (2.0f * radius), 0.5f - dot(q, up) / (2.0f * radius), dot(q, d));
}

/// Where cell coordinates `st` (tsImpostorProject's s and t) fall inside a
/// cell, in mip-0 texels from the cell's top-left corner (texel centres at
/// n + 0.5): the square [0, 1]^2 spans the CELL - 2 BORDER inner texels, so
/// the BORDER texels round it stay empty. The baker rasterises with this
/// mapping; a card corner's texture coordinate is tsImpostorLayerUv.
TS_INLINE vec2 tsImpostorCellTexel(vec2 st) {
    return vec2(float(TS_IMPOSTOR_BORDER)) + st * float(TS_IMPOSTOR_CELL - 2u * TS_IMPOSTOR_BORDER);
}

/// The texture coordinate in [0, 1]^2 of a layer (any mip level: a cell is
/// CELL >> m texels a side at mip m, so cells stay aligned) of the point at
/// cell coordinates `st` of cell `cell`. A card drawn over the sphere's
/// square with st = (0, 0) at its top-left corner (towards -right, +up) and
/// (1, 1) at its bottom-right shows the cell exactly as baked.
TS_INLINE vec2 tsImpostorLayerUv(uvec2 cell, vec2 st) {
    return (vec2(cell) * float(TS_IMPOSTOR_CELL) + tsImpostorCellTexel(st)) /
           float(TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL);
}

/// A cell's covered rectangle (over every layer of a creature), packed in
/// one uint: x0, y0, x1, y1 in cell texels at mip 0 (0 to TS_IMPOSTOR_CELL,
/// border included; x1 and y1 past the last covered texel), a byte each.
/// The cards are drawn over it alone: a creature fills about a fifth of
/// the sphere's square, and every fragment outside it would be shaded and
/// discarded.
TS_INLINE uint tsImpostorPackBounds(uint x0, uint y0, uint x1, uint y1) {
    return x0 | (y0 << 8u) | (x1 << 16u) | (y1 << 24u);
}

/// The cell coordinates (s0, t0, s1, t1) of packed bounds (the inverse of
/// tsImpostorCellTexel: outside [0, 1] where they reach into the border).
TS_INLINE vec4 tsImpostorBoundsSt(uint packed) {
    const float inner = float(TS_IMPOSTOR_CELL - 2u * TS_IMPOSTOR_BORDER), b = float(TS_IMPOSTOR_BORDER);
    return vec4(float(packed & 255u) - b, float((packed >> 8u) & 255u) - b, float((packed >> 16u) & 255u) - b,
                float(packed >> 24u) - b) /
           inner;
}

/// The layer and weight of the two phases around `phase` of a clip of
/// `looping` kind (as tsBakedFramePair: a looping clip wraps, any other
/// clamps): layers first + k, first + k2 and the weight of the second.
TS_INLINE float tsImpostorPhasePair(float phase, bool looping, uint firstLayer, TS_OUT(uint) layer0,
                                    TS_OUT(uint) layer1) {
    const float n = float(TS_IMPOSTOR_PHASES);
    float x;
    if (looping)
        x = (phase - floor(phase)) * n;
    else
        x = clamp(phase, 0.0f, 1.0f) * (n - 1.0f);
    const float k = min(floor(x), n - 1.0f);
    layer0 = firstLayer + uint(k);
    const uint next = looping ? (uint(k) + 1u) % TS_IMPOSTOR_PHASES : min(uint(k) + 1u, TS_IMPOSTOR_PHASES - 1u);
    layer1 = firstLayer + next;
    return clamp(x - k, 0.0f, 1.0f);
}

TS_NAMESPACE_END

#endif
