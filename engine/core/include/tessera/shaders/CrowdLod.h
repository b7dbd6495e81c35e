// CrowdLod.h: the crowd's level-of-detail selection, one definition for the
// CPU reference (lod::LodManager, the null backend and the tests) and for the
// backends' GPU culling and binning passes (a compute pass, a geometry
// shader, a render-target pass), so every path sorts an instance into the
// same tier from the same numbers.
//
// Per instance and frame (tsLodUpdate):
//   1. frustum test of the instance's bounding sphere, and the horizon: the
//      terrain's lowest drawn heights between the eye and the sphere
//      (tsLodBehindTerrain);
//   2. its projected size in pixels (the sphere's diameter on screen);
//   3. the tier it would take from the thresholds, with hysteresis: moving
//      to a finer tier needs the threshold, moving back needs falling a
//      hysteresis fraction below it, so an instance on a boundary does not
//      flicker;
//   4. the frame budget, which the CPU turns into pixel cuts and a level cap
//      per frame (lod::LodManager): a near candidate below the near cut is
//      drawn in the middle tier, a middle candidate below the middle cut in
//      the far tier, a far one below the far cut as an impostor (which has
//      no budget: every instance in view is drawn);
//   5. the cross-fade: a tier change draws the instance in both tiers for
//      `fadeFrames` frames with complementary dither masks.
// The instance's state between frames is one uint (tier, previous tier,
// fade frames left), kept per instance id by whoever runs the selection.
#ifndef TESSERA_CROWD_LOD_H
#define TESSERA_CROWD_LOD_H
#include "tessera/shaders/SharedTypes.h"

/// Tiers, finest first.
#define TS_LOD_NEAR 0u   ///< tessellated and displaced (the two-pass path)
#define TS_LOD_MIDDLE 1u ///< the cage, untessellated, with the normal map
#define TS_LOD_FAR 2u    ///< the simplified far mesh
#define TS_LOD_IMPOSTOR 3u ///< one card per creature from its baked views (CrowdImpostor.h)
#define TS_LOD_TIERS 4u
/// State tier of an instance that was not in view last frame.
#define TS_LOD_NONE 4u

/// Most frames a cross-fade may last (the fade counter has 6 bits).
#define TS_LOD_MAX_FADE_FRAMES 63u

TS_NAMESPACE_BEGIN

/// What the selection reads per frame (a uniform block on the GPU).
struct CrowdLodParams {
    vec4 planes[6];  // world frustum planes, normals inwards (scene::Frustum's order)
    vec4 eye;        // xyz: camera position, w: pixels per radian (viewport height / (2 tan(fov / 2)))
    vec4 thresholds; // x: near threshold (px), y: far threshold (px), z: hysteresis fraction, w: fade frames
    vec4 cuts;       // x: near cut, y: middle cut, z: far cut (px; against tsLodFarRank), w: bit t set = the
                     // budget's demotions out of tier t fade
    vec4 levels;     // x: level cap of the near tier, y: fixed level (0: from the size), z: impostor threshold
                     // (px; 0: no impostors by size), w: the budgets' hold on incumbents, 1 / (1 - hysteresis)
    vec4 occluder;   // the horizon's grid: xy its min corner (world x, z), z: cell side (m), w: cells per
                     // side (0: no horizon occlusion)
};
TS_CHECK_SIZE(CrowdLodParams, 176)

// The horizon's grid, cell (i, j) the lowest height the terrain is drawn at
// over it (the lowest sample its patch interpolates: every tessellation of
// the patch lies at or above it). In C++ the grid is the selection's last
// argument (nullptr: none); a GLSL shader that runs the selection defines
// tsLodOccluderMin (crowd_occluders.glsl reads TS_BINDING_CROWD_OCCLUDERS).
#ifdef __cplusplus
#define TS_LOD_OCCLUDERS_PARAM , const float* occluders
#define TS_LOD_OCCLUDERS_ARG , occluders
#define TS_LOD_OCCLUDER_MIN(i, j, n) occluders[(j) * (n) + (i)]
#define TS_LOD_HAS_OCCLUDERS (occluders != nullptr)
#else
#define TS_LOD_OCCLUDERS_PARAM
#define TS_LOD_OCCLUDERS_ARG
float tsLodOccluderMin(uint i, uint j, uint n);
#define TS_LOD_OCCLUDER_MIN(i, j, n) tsLodOccluderMin(i, j, n)
#define TS_LOD_HAS_OCCLUDERS true
#endif
/// Metres a sight line must pass below a cell's lowest height to count as
/// blocked: float rounding never decides.
#define TS_LOD_OCCLUSION_MARGIN 0.05f
/// Most points a sight line is tested at.
#define TS_LOD_OCCLUSION_STEPS 64u

/// The state word: tier in bits 0..2, previous tier in bits 3..5, fade
/// frames left in bits 6..11.
TS_INLINE uint tsLodStateTier(uint state) { return state & 7u; }
TS_INLINE uint tsLodStatePrevious(uint state) { return (state >> 3u) & 7u; }
TS_INLINE uint tsLodStateFade(uint state) { return (state >> 6u) & 63u; }
TS_INLINE uint tsLodState(uint tier, uint previous, uint fade) { return tier | (previous << 3u) | (fade << 6u); }
/// The state of an instance never seen (or out of view last frame).
TS_INLINE uint tsLodStateNone() { return tsLodState(TS_LOD_NONE, TS_LOD_NONE, 0u); }

/// Whether the sphere (xyz centre, w radius) is at least partly inside.
TS_INLINE bool tsLodInFrustum(vec4 sphere, CrowdLodParams p) {
    bool inside = true;
    for (uint i = 0u; i < 6u; ++i)
        if (dot(vec3(p.planes[i].x, p.planes[i].y, p.planes[i].z), vec3(sphere.x, sphere.y, sphere.z)) +
                p.planes[i].w < -sphere.w)
            inside = false;
    return inside;
}

/// Whether the terrain hides the sphere from the eye. The sight lines from
/// the eye to the sphere fill a cone; at a fraction t of the way to the
/// sphere's centre they lie within t r d / sqrt(d^2 - r^2) of the axis. If
/// at some point short of the sphere that whole cross-section lies over the
/// grid and below its lowest drawn height there, every sight line
/// passes below the drawn terrain there, with the eye above it (the camera
/// keeps its height over the drawn ground), so each meets the terrain
/// before the sphere. The cross-section is taken by its square and the
/// lowest of the cells the square overlaps. Points every half cell (at most
/// TS_LOD_OCCLUSION_STEPS), from the eye.
///
/// tsLodSight sets the test up for one sphere: `delta` the eye-to-centre
/// vector (xyz) and its length (w), `cone` the spread and the fraction of
/// the way the points reach; returns how many points (0: too close to test).
TS_INLINE uint tsLodSight(vec4 sphere, CrowdLodParams p, TS_OUT(vec4) delta, TS_OUT(vec2) cone) {
    const float cell = p.occluder.z;
    const float dx = sphere.x - p.eye.x, dy = sphere.y - p.eye.y, dz = sphere.z - p.eye.z;
    const float d = sqrt(dx * dx + dy * dy + dz * dz);
    const float r = sphere.w;
    delta = vec4(dx, dy, dz, d);
    cone = vec2(0.0f, 0.0f);
    if (d <= 2.0f * r + cell) return 0u;
    const float spread = r / sqrt(d * d - r * r);
    const float reach = (d - r) / d; // the sight lines meet the sphere beyond it
    cone = vec2(spread, reach);
    const float across = sqrt(dx * dx + dz * dz);
    return min(uint(across / (0.5f * cell)) + 1u, TS_LOD_OCCLUSION_STEPS);
}

/// Point `s` (1..steps) of the sight set up by tsLodSight: a fraction t of
/// the way, where the cone's cross-section is a square of half side rho.
TS_INLINE vec4 tsLodSightPoint(uint s, uint steps, vec4 delta, vec2 cone, CrowdLodParams p) {
    const float t = cone.y * float(s) / float(steps + 1u);
    const float x = p.eye.x + t * delta.x - p.occluder.x, z = p.eye.z + t * delta.z - p.occluder.y;
    const float y = p.eye.y + t * delta.y;
    return vec4(x, y, z, t * delta.w * cone.x);
}

/// Whether every sight line passes below the lowest height of the cells
/// the cross-section at point `s` overlaps (at most two a side while it is
/// narrower than a cell, all inside the grid).
TS_INLINE bool tsLodSightBlockedAt(uint s, uint steps, vec4 delta, vec2 cone, CrowdLodParams p TS_LOD_OCCLUDERS_PARAM) {
    const uint n = uint(p.occluder.w);
    const float cell = p.occluder.z;
    const vec4 q = tsLodSightPoint(s, steps, delta, cone, p);
    const float rho = q.w;
    if (2.0f * rho >= cell) return false;
    const float i0 = floor((q.x - rho) / cell), i1 = floor((q.x + rho) / cell);
    const float j0 = floor((q.z - rho) / cell), j1 = floor((q.z + rho) / cell);
    if (i0 < 0.0f || j0 < 0.0f || i1 >= float(n) || j1 >= float(n)) return false;
    const uint a = uint(i0), b = uint(i1), c = uint(j0), e = uint(j1);
    const float lowest = min(min(TS_LOD_OCCLUDER_MIN(a, c, n), TS_LOD_OCCLUDER_MIN(b, c, n)),
                             min(TS_LOD_OCCLUDER_MIN(a, e, n), TS_LOD_OCCLUDER_MIN(b, e, n)));
    return q.y + rho + TS_LOD_OCCLUSION_MARGIN < lowest;
}

/// The whole test (above): true when some point's cross-section is blocked.
/// lod::LodManager runs the same points through a pyramid that skips runs of
/// them none of which can be blocked (HorizonPyramid), with the same answer.
TS_INLINE bool tsLodBehindTerrain(vec4 sphere, CrowdLodParams p TS_LOD_OCCLUDERS_PARAM) {
    if (uint(p.occluder.w) == 0u || !TS_LOD_HAS_OCCLUDERS) return false;
    vec4 delta;
    vec2 cone;
    const uint steps = tsLodSight(sphere, p, delta, cone);
    for (uint s = 1u; s <= steps; ++s)
        if (tsLodSightBlockedAt(s, steps, delta, cone, p TS_LOD_OCCLUDERS_ARG)) return true;
    return false;
}

/// The sphere's diameter on screen in pixels (its full height when the
/// camera is inside it).
TS_INLINE float tsLodPixels(vec4 sphere, CrowdLodParams p) {
    const float distance = length(vec3(sphere.x, sphere.y, sphere.z) - vec3(p.eye.x, p.eye.y, p.eye.z));
    return 2.0f * sphere.w * p.eye.w / max(distance, sphere.w);
}

/// The tier the thresholds give, with hysteresis against `previous` (the
/// instance's tier last frame, or TS_LOD_NONE). Below the impostor
/// threshold (levels.z; 0: none) a creature takes the impostor tier.
TS_INLINE uint tsLodCandidate(float pixels, uint previous, CrowdLodParams p) {
    const float keep = 1.0f - p.thresholds.z;
    const bool wasNear = previous == TS_LOD_NEAR;
    const bool wasFiner = previous <= TS_LOD_MIDDLE;
    const bool wasMesh = previous <= TS_LOD_FAR;
    if (pixels >= p.thresholds.x || (wasNear && pixels >= p.thresholds.x * keep)) return TS_LOD_NEAR;
    if (pixels >= p.thresholds.y || (wasFiner && pixels >= p.thresholds.y * keep)) return TS_LOD_MIDDLE;
    if (pixels >= p.levels.z || (wasMesh && pixels >= p.levels.z * keep)) return TS_LOD_FAR;
    return TS_LOD_IMPOSTOR;
}

/// The size the far tier's budget ranks an instance by: one already there
/// (`last`) counts a hysteresis fraction larger (levels.w), so in a crowd of
/// nearly equal sizes (thousands of far agents, the budget spent) the moving
/// agents do not trade places with impostors at the cut every frame.
TS_INLINE float tsLodFarRank(float pixels, uint last, CrowdLodParams p) {
    return last == TS_LOD_FAR ? pixels * max(p.levels.w, 1.0f) : pixels;
}

/// The tier after the budget's cuts: a candidate below its tier's cut goes
/// to the next coarser tier; the impostor tier has no budget, so every
/// instance in view is drawn (the budgets choose how, never whether).
TS_INLINE uint tsLodTier(float pixels, uint candidate, uint last, CrowdLodParams p) {
    if (candidate == TS_LOD_NEAR && pixels >= p.cuts.x) return TS_LOD_NEAR;
    if (candidate <= TS_LOD_MIDDLE && pixels >= p.cuts.y) return TS_LOD_MIDDLE;
    if (candidate <= TS_LOD_FAR && tsLodFarRank(pixels, last, p) >= p.cuts.z) return TS_LOD_FAR;
    return TS_LOD_IMPOSTOR;
}

/// The next state of an instance in view (`state`: last frame's) of
/// `pixels` on screen whose thresholds gave `candidate` (tsLodCandidate
/// against last frame's tier). Coming into view: its tier at once (nothing
/// on screen to fade from). A change of tier starts a fade; a demotion by
/// the budget fades only when the budget leaves room for the fading copies
/// (cuts.w, per tier left).
TS_INLINE uint tsLodNext(uint state, float pixels, uint candidate, CrowdLodParams p) {
    const uint last = tsLodStateTier(state);
    const uint tier = tsLodTier(pixels, candidate, last, p);
    if (last == TS_LOD_NONE) return tsLodState(tier, tier, 0u);
    const uint fadeFrames = uint(p.thresholds.w);
    if (tier != last) {
        const bool byBudget = tier != candidate;
        const bool budgetFades = (uint(p.cuts.w) & (1u << last)) != 0u;
        const uint fade = (byBudget && !budgetFades) ? 0u : fadeFrames;
        return tsLodState(tier, last, fade);
    }
    const uint fade = tsLodStateFade(state);
    return tsLodState(tier, tsLodStatePrevious(state), fade > 0u ? fade - 1u : 0u);
}

/// The next state of an instance (`state`: last frame's). Out of view
/// (outside the frustum or behind the terrain): none.
TS_INLINE uint tsLodUpdate(uint state, vec4 sphere, CrowdLodParams p TS_LOD_OCCLUDERS_PARAM) {
    if (!tsLodInFrustum(sphere, p) || tsLodBehindTerrain(sphere, p TS_LOD_OCCLUDERS_ARG)) return tsLodStateNone();
    const float pixels = tsLodPixels(sphere, p);
    return tsLodNext(state, pixels, tsLodCandidate(pixels, tsLodStateTier(state), p), p);
}

/// How much of the instance its tier draws, in (0, 1]: the fade's progress
/// (the previous tier draws the rest, 1 - coverage).
TS_INLINE float tsLodCoverage(uint state, CrowdLodParams p) {
    const uint fade = tsLodStateFade(state);
    if (fade == 0u) return 1.0f;
    return 1.0f - float(fade) / (p.thresholds.w + 1.0f);
}

/// The tessellation level of a near instance: its size on screen times the
/// character's levels per pixel (or the fixed level), within [1, the
/// frame's cap].
TS_INLINE float tsLodLevel(float pixels, float levelPerPixel, CrowdLodParams p) {
    const float level = p.levels.y > 0.0f ? p.levels.y : pixels * levelPerPixel;
    return clamp(level, 1.0f, p.levels.x);
}

TS_NAMESPACE_END

#endif
