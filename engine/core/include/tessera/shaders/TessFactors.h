// TessFactors.h: the adaptive tessellation metrics, one formula for the CPU
// reference (terrain::TessellationSettings tests, triangle estimates) and the
// factor pre-pass shaders of every backend.
//
// Every metric maps one canonical edge (endpoints a, b in world space, in the
// order TerrainPatches.h defines) to a level before clamping. A shared edge is
// evaluated once per frame and stored, so neighbouring patches always agree.
#ifndef TESSERA_TESS_FACTORS_H
#define TESSERA_TESS_FACTORS_H
#include "tessera/shaders/SharedTypes.h"

// Metric ids; terrain::TessMetric uses the same values.
#define TS_METRIC_SCREEN 0u
#define TS_METRIC_DISTANCE 1u
#define TS_METRIC_SILHOUETTE 2u
#define TS_METRIC_DETAIL 3u

// Bindings of the tessellated terrain passes (after TS_BINDING_HEIGHTMAP).
#define TS_BINDING_TESS 3
#define TS_BINDING_EDGE_ERROR 4
#define TS_BINDING_PATCH_ERROR 5
#define TS_BINDING_EDGE_LEVELS 6
#define TS_BINDING_PATCH_LEVELS 7

#define TS_TERRAIN_MODE_LOWRES 0u
#define TS_TERRAIN_MODE_CONTINUOUS 1u
#define TS_TERRAIN_MODE_ADAPTIVE 2u

TS_NAMESPACE_BEGIN

/// Per-frame tessellation settings of one terrain draw.
struct TerrainTessUniforms {
    vec4 levels;  // x: min level, y: max level, z: continuous level, w: unused
    vec4 metric;  // x: target pixels, y: distance of max level..min level (m), z: pixels per metre at 1 m, w: unused
    uvec4 mode;   // x: TS_TERRAIN_MODE_*, y: TS_METRIC_*, z: patches per side, w: edge count
};
TS_CHECK_SIZE(TerrainTessUniforms, 48)

/// Screen-space edge length: the projected diameter, in pixels, of the sphere
/// around the edge, divided by the target edge length. Using the sphere (not
/// the projected endpoints) makes the level independent of the view direction,
/// so turning the camera never changes the mesh, and of the edge's direction.
/// `pixelsPerMetre` is viewport height * projection[1][1] / 2: pixels covered
/// by one metre seen face-on from one metre away.
TS_INLINE float tsScreenEdgeLevel(vec3 a, vec3 b, vec3 eye, float pixelsPerMetre, float targetPixels) {
    vec3 middle = (a + b) * 0.5f;
    float diameter = length(b - a);
    float distance = max(length(middle - eye), diameter * 0.5f);
    return diameter * pixelsPerMetre / (distance * targetPixels);
}

/// Distance to the camera, after the first paper's Listing 15: the maximum
/// level at the eye falling linearly to the minimum at `farDistance`.
TS_INLINE float tsDistanceLevel(vec3 a, vec3 b, vec3 eye, float farDistance, float minLevel, float maxLevel) {
    float distance = length((a + b) * 0.5f - eye);
    float t = clamp(distance / farDistance, 0.0f, 1.0f);
    return mix(maxLevel, minLevel, t);
}

/// Silhouette: edges where the surface turns away from the viewer (normals
/// across the view direction, or facing opposite ways at the two ends) get the
/// full screen-space level; edges facing the viewer get a quarter of it, as
/// their interior detail shows only through shading, which comes from the
/// height map per pixel anyway.
TS_INLINE float tsSilhouetteLevel(vec3 a, vec3 b, vec3 normalA, vec3 normalB, vec3 eye, float pixelsPerMetre,
                                  float targetPixels) {
    float facingA = dot(normalA, normalize(eye - a));
    float facingB = dot(normalB, normalize(eye - b));
    float grazing = facingA * facingB <= 0.0f ? 0.0f : min(abs(facingA), abs(facingB));
    float weight = 1.0f - clamp(grazing / 0.35f, 0.0f, 1.0f);
    return tsScreenEdgeLevel(a, b, eye, pixelsPerMetre, targetPixels) * mix(0.25f, 1.0f, weight * weight);
}

/// Height-map detail: `errorMetres` is how far the height field strays from
/// the straight (untessellated) edge or patch. Projected to pixels, it must
/// fall under the target; splitting a curved span into n parts divides that
/// error by about n^2, hence the square root. Flat ground stays at the
/// minimum level and ridges get many triangles.
TS_INLINE float tsDetailLevel(vec3 a, vec3 b, vec3 eye, float errorMetres, float pixelsPerMetre, float targetPixels) {
    float distance = max(length((a + b) * 0.5f - eye), 1.0f);
    float errorPixels = errorMetres * pixelsPerMetre / distance;
    return sqrt(max(errorPixels, 0.0f) / targetPixels);
}

TS_NAMESPACE_END

#endif
