// lod_fade.glsl: what a crowd instance's pixels do during a LOD cross-fade,
// and the --lod-colors tint, for every pass that draws a tier (CrowdLod.h).
//
// A tier change draws the instance twice for a few frames: the incoming
// tier keeps the pixels whose ordered-dither threshold is below its
// coverage, the outgoing copy exactly the others, so together they cover
// every pixel once (no blending, no sorting, depth writes stay on) and the
// share moves from one to the other frame by frame.
#ifndef LOD_FADE_GLSL
#define LOD_FADE_GLSL
#include "tessera/shaders/CrowdLod.h"

// 4x4 Bayer matrix thresholds, (rank + 0.5) / 16.
float tsLodDitherThreshold(vec2 fragCoord) {
    const float bayer[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0,
                                      13.0, 5.0);
    ivec2 p = ivec2(fragCoord) & 3;
    return (bayer[p.y * 4 + p.x] + 0.5) / 16.0;
}

// Whether this pixel belongs to this draw of the instance.
bool tsLodKeepPixel(vec2 fragCoord, float coverage, bool fadingOut) {
    if (coverage >= 1.0) return true;
    float t = tsLodDitherThreshold(fragCoord);
    return fadingOut ? t >= 1.0 - coverage : t < coverage;
}

// --lod-colors: near green, middle yellow, far red, impostor blue.
vec3 tsLodTierTint(uint tier) {
    if (tier == TS_LOD_NEAR) return vec3(0.25, 0.9, 0.3);
    if (tier == TS_LOD_MIDDLE) return vec3(0.95, 0.85, 0.2);
    if (tier == TS_LOD_FAR) return vec3(0.95, 0.3, 0.25);
    return vec3(0.3, 0.5, 0.95);
}

#endif
