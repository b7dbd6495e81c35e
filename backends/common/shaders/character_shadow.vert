#version 450
// One character's shadow on the ground, as the terrain-space mask sees it:
// an ellipse around the feet stretched away from the sun by the length of
// the shadow a character of that height casts (capped near the horizon).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CharacterShadow.h"

layout(push_constant) uniform Push { CharacterShadowParams shadow; };

layout(location = 0) in vec4 inCaster; // xyz: feet (world), w: height (metres)
layout(location = 0) out vec2 outEllipse;

void main() {
    // A quad of two triangles from the vertex index alone.
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    vec2 corner = corners[gl_VertexIndex];
    float height = inCaster.w;
    float width = 0.24 * height;
    vec2 towardsSun = shadow.sun.xz;
    float horizontal = length(towardsSun);
    vec2 along = horizontal > 1e-4 ? -towardsSun / horizontal : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    float length_ = min(height * horizontal / max(shadow.sun.y, 1e-3), shadow.sun.w * height);
    float halfAlong = 0.5 * length_ + width;
    vec2 centre = inCaster.xz + along * (0.5 * length_);
    vec2 world = centre + along * (corner.x * halfAlong) + across * (corner.y * width);
    vec2 uv = (world - shadow.region.xy) * shadow.region.w;
    outEllipse = corner;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
