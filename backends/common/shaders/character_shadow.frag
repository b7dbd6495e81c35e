#version 450
// Soft-edged coverage of the ellipse; blended over the mask so overlapping
// shadows darken towards full shadow, never past it.
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CharacterShadow.h"

layout(location = 0) in vec2 inEllipse;
layout(location = 0) out vec4 outDarkness;

void main() {
    float r = length(inEllipse);
    float coverage = 1.0 - smoothstep(0.55, 1.0, r);
    outDarkness = vec4(1.0, 1.0, 1.0, coverage);
}
