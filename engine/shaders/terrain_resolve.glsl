// terrain_resolve.glsl: the full look's deferred terrain shading
// (docs/LOOKS.md, "Deferred terrain shading"). The terrain is a height
// field, so a pixel's distance along its view ray is all its shading needs:
// position from the camera and the ray, normal and materials from the
// height map there. In the main pass the terrain's fragments store that
// distance in the target's RGB (24-bit fixed point, 4 mm steps: the depth
// buffer's float steps reach metres kilometres away, which would speckle the
// materials' noise) with alpha 0; the resolve then shades each such pixel
// once (no overdraw, no partly covered 2x2 quads of small tessellated
// triangles) and keeps the pixels other geometry shaded forward (alpha 1).
// The clear value (white, alpha 0) is the largest distance: nothing drawn,
// the sky. terrain_resolve.comp runs it in compute (hulldomain, the sky
// too), terrain_resolve.frag as a fullscreen pass (r2vb, streamout: no
// compute; the sky pass draws the sky).
#ifndef TERRAIN_RESOLVE_GLSL
#define TERRAIN_RESOLVE_GLSL
#include "terrain_heightmap.glsl"
#include "terrain_shading.glsl"
#include "output_color.glsl"

const uint kTsResolveSky = 16777215u; // 2^24 - 1: the clear value

// The distance `t` (metres) as three UNORM8 channels; exact through the
// target since each channel is k / 255.
vec3 tsPackResolveDistance(float t) {
    uint q = uint(clamp(t / TS_RESOLVE_MAX_DISTANCE, 0.0, 1.0) * float(kTsResolveSky) + 0.5);
    return vec3(float(q >> 16), float((q >> 8) & 255u), float(q & 255u)) / 255.0;
}

// What the main pass stored, in steps of TS_RESOLVE_MAX_DISTANCE / 2^24.
uint tsResolveSteps(vec3 stored) {
    uvec3 b = uvec3(stored * 255.0 + 0.5);
    return (b.x << 16) | (b.y << 8) | b.z;
}

// The unit view ray through the centre of pixel `pixel`: in view space from
// the projection's scales, then turned by the view's rotation (a rigid
// transform, so its inverse is its transpose). Well conditioned, unlike a
// far-plane point through the inverse view-projection, whose float error
// moves the point decimetres a kilometre away.
vec3 tsResolveViewRay(ivec2 pixel) {
    vec2 ndc = (vec2(pixel) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
    vec3 viewDir = vec3(ndc * frame.terrainResolve.zw, -1.0);
    return normalize(viewDir * mat3(frame.view));
}

// The terrain's full look at `steps` along `dir`.
vec4 tsResolveTerrain(vec3 dir, uint steps) {
    vec3 p = frame.cameraPosition.xyz + dir * (float(steps) * (TS_RESOLVE_MAX_DISTANCE / float(kTsResolveSky)));
    return tsOutputColor(shadeTerrainFull(p, terrainNormal(p.xz)));
}

// The sky towards `dir`, as the sky pass draws it.
vec4 tsResolveSky(vec3 dir) {
    return tsOutputColor(tsFogColor(dir) + tsSunDisc(dir));
}

#endif
