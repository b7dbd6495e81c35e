// CraterProfile.h: the crater a splat adds to the terrain, for the CPU copy
// of the height field (terrain::applyCrater) and the GPU splat pass alike, so
// both copies change by the same formula.
#ifndef TESSERA_CRATER_PROFILE_H
#define TESSERA_CRATER_PROFILE_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

/// One splat as the GPU pass reads it (push constants).
struct CraterSplatParams {
    vec4 centerRadius; // x: centre x (m), y: centre z (m), z: radius (m), w: sample spacing (m)
    vec4 profile;      // x: depth (m), y: rim height (m), z: rim position (fraction of radius), w: height scale (m at 1.0)
};
TS_CHECK_SIZE(CraterSplatParams, 32)

/// Height offset in metres at normalised distance x = distance / radius from
/// the centre: a parabolic bowl `depth` deep at the centre rising to a rim
/// `rim` high at x = rimAt, then a smooth (C1) fall to exactly zero at the
/// radius. Zero at and beyond x = 1, so a splat never touches anything
/// outside its radius.
TS_INLINE float tsCraterOffset(float x, float depth, float rim, float rimAt) {
    if (x >= 1.0f) return 0.0f;
    if (x <= rimAt) {
        float t = x / rimAt;
        return -depth + (depth + rim) * t * t;
    }
    float t = (x - rimAt) / (1.0f - rimAt);
    return rim * (1.0f - t * t * (3.0f - 2.0f * t));
}

/// The crater's change of a sample at squared distance `distanceSq` (m^2)
/// from the centre, in 16-bit height units, rounded half up. Zero at and
/// beyond the radius. Both copies add it to the sample as an integer
/// (clamped to 0..65535): integer arithmetic after this point means the CPU
/// and GPU copies can differ only where float rounding of the offset itself
/// lands on the other side of a half unit, and differences cannot build up
/// as craters overlap.
TS_INLINE int tsCraterDelta(float distanceSq, CraterSplatParams p) {
    float radius = p.centerRadius.z;
    if (distanceSq >= radius * radius) return 0;
    float offset = tsCraterOffset(sqrt(distanceSq) / radius, p.profile.x, p.profile.y, p.profile.z);
    return int(floor(offset / p.profile.w * 65535.0f + 0.5f));
}

TS_NAMESPACE_END

#endif
