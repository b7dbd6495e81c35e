// output_color.glsl: the one way a colour reaches the main target. Every
// fragment shader that writes it calls tsOutputColor with its linear
// radiance. The target stays R8G8B8A8_UNORM (the readback, the PNGs and the
// swapchain blit copy bytes as they are), so the sRGB encode happens here.
//
// Full look: exposure, the ACES filmic fit (Narkowicz 2015, a curve with a
// toe and a soft shoulder, so bright snow and the sun's halo roll off instead
// of clipping), then the exact piecewise linear->sRGB transfer function.
// Plain look: the value as it was written before the looks, unencoded.
#ifndef OUTPUT_COLOR_GLSL
#define OUTPUT_COLOR_GLSL
#include "common_frame.glsl"

bool tsFullLook() { return uint(frame.look.x) == TS_LOOK_FULL; }

vec3 tsAcesFilmic(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// The exact piecewise transfer function.
vec3 tsLinearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 low = c * 12.92;
    vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(c, vec3(0.0031308)));
}

// The same curve fitted with three square roots instead of pow, which a CPU
// rasterizer (lavapipe) evaluates as exp2(log2) per channel: within 0.2% of
// tsLinearToSrgb on [0.0031308, 1] (under half an 8-bit step), the linear
// segment below.
vec3 tsLinearToSrgbFast(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    vec3 s1 = sqrt(c);
    vec3 s2 = sqrt(s1);
    vec3 s3 = sqrt(s2);
    vec3 high = 0.662002687 * s1 + 0.684122060 * s2 - 0.323583601 * s3 - 0.0225411470 * c;
    return mix(high, c * 12.92, lessThanEqual(c, vec3(0.0031308)));
}

// The inverse, for colour constants written as sRGB (what a colour picker shows).
vec3 tsSrgbToLinear(vec3 c) {
    vec3 low = c / 12.92;
    vec3 high = pow((c + 0.055) / 1.055, vec3(2.4));
    return mix(high, low, lessThanEqual(c, vec3(0.04045)));
}

vec4 tsOutputColor(vec3 radiance) {
    if (!tsFullLook()) return vec4(radiance, 1.0);
    return vec4(tsLinearToSrgbFast(tsAcesFilmic(radiance * frame.look.y)), 1.0);
}

#endif
