// sky_atmosphere.glsl: the daylight sky and the aerial-perspective fog, one
// model for both, so distant terrain, characters and surfaces melt into the
// sky behind them with the same colour (docs/LOOKS.md).
//
// The sky is analytic, in linear radiance: a zenith-to-horizon gradient for
// the Rayleigh scattering (the air's optical depth grows towards the
// horizon, which whitens it), brightened by the Rayleigh phase function
// (1 + cos^2) around the sun's axis, a Henyey-Greenstein halo for the Mie
// (haze) forward scattering, and the sun's disc. Everything follows
// FrameUniforms::sunDirection and sunColor.
//
// The fog is exponential in distance and in height: its density falls off as
// exp(-falloff * (y - reference)), integrated along the view ray in closed
// form, so valleys hold haze and peaks stand out. Its colour is the sky's in
// the view direction (the horizon's for rays below it) plus the sun's
// in-scatter, so a view towards the sun glows.
#ifndef SKY_ATMOSPHERE_GLSL
#define SKY_ATMOSPHERE_GLSL
#include "output_color.glsl"

const float kTsPi = 3.14159265;

vec3 tsSunDirection() { return normalize(frame.sunDirection.xyz); }

float tsHenyeyGreenstein(float cosTheta, float g) {
    float denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * kTsPi * denom * sqrt(denom));
}

// Sky radiance towards unit direction `dir` (at or above the horizon:
// tsFogColor lifts rays below it), without the sun's disc.
vec3 tsSkyRadiance(vec3 dir) {
    vec3 sun = tsSunDirection();
    float mu = dot(dir, sun);
    float up = max(dir.y, 0.0);
    // Optical depth ~ 1/cos(zenith angle): the horizon sees the most air.
    float x = 1.0 - up;
    float x2 = x * x;
    float horizonness = x2 * x2 * x2 * x; // (1 - up)^7, without pow's exp2(log2)
    const vec3 zenith = vec3(0.030, 0.105, 0.40);
    const vec3 horizon = vec3(0.46, 0.60, 0.80);
    vec3 sky = mix(zenith, horizon, horizonness);
    sky *= 0.85 + 0.35 * mu * mu;                       // Rayleigh phase, relative
    // The sun lower in the sky warms the horizon on its side.
    float low = 1.0 - clamp(sun.y, 0.0, 1.0);
    sky += vec3(0.35, 0.18, 0.05) * low * low * horizonness * max(mu, 0.0);
    // Mie halo: strong forward lobe, more haze near the horizon.
    sky += frame.sunColor.rgb * tsHenyeyGreenstein(mu, 0.78) * (0.035 + 0.06 * horizonness);
    return sky;
}

// The sun's disc with a soft limb, added to the sky where no geometry covers it.
vec3 tsSunDisc(vec3 dir) {
    float mu = dot(dir, tsSunDirection());
    float cosRadius = frame.sunColor.a;
    float edge = (1.0 - cosRadius) * 0.35;
    return frame.sunColor.rgb * 12.0 * smoothstep(cosRadius - edge, cosRadius + edge, mu);
}

// The fog's colour towards `dir`: the sky at or above the horizon, plus the
// sun's in-scattered light, strongest looking towards it.
vec3 tsFogColor(vec3 dir) {
    vec3 skyDir = normalize(vec3(dir.x, max(dir.y, 0.0), dir.z) + vec3(0.0, 1e-4, 0.0));
    float mu = max(dot(dir, tsSunDirection()), 0.0);
    float mu4 = (mu * mu) * (mu * mu);
    return tsSkyRadiance(skyDir) + frame.sunColor.rgb * 0.12 * (mu4 * mu4 * mu4); // mu^12
}

// Fogs the linear radiance `color` of a surface at `worldPos`. The plain look
// keeps the old distance fog towards FrameUniforms::fogColor.
vec3 tsApplyFog(vec3 color, vec3 worldPos) {
    vec3 toPoint = worldPos - frame.cameraPosition.xyz;
    float dist = length(toPoint);
    if (!tsFullLook()) {
        float fog = 1.0 - exp(-dist * frame.fogColor.a);
        return mix(color, frame.fogColor.rgb, clamp(fog, 0.0, 1.0));
    }
    vec3 dir = toPoint / max(dist, 1e-4);
    float falloff = frame.look.z;
    // Density at the camera (look.w, computed once on the host), then the
    // integral of exp(-falloff * dy) along the ray.
    float density = frame.look.w;
    float dy = falloff * toPoint.y;
    float path = abs(dy) > 1e-4 ? (1.0 - exp(-dy)) / dy : 1.0;
    float opticalDepth = density * dist * path;
    float fog = 1.0 - exp(-opticalDepth);
    return mix(color, tsFogColor(dir), clamp(fog, 0.0, 1.0));
}

// Light from the sky hemisphere on a surface facing `n` (the ambient term):
// the zenith's colour above, a warm bounce from the ground below.
vec3 tsSkyAmbient(vec3 n) {
    float hemi = 0.5 + 0.5 * n.y;
    return mix(vec3(0.11, 0.09, 0.07), vec3(0.20, 0.30, 0.48), hemi);
}

#endif
