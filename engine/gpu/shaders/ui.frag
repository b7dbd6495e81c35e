#version 450
// The overlay's pixels: vertex colour times the font atlas's coverage. The
// colours are display values written straight into the target, which holds
// display-encoded bytes (the scene's shaders encode before writing).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/UiConstants.h"

layout(set = 0, binding = TS_BINDING_UI_FONT) uniform sampler2D uFont;

layout(location = 0) in vec2 inUv;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 outColor;

void main() { outColor = inColor * texture(uFont, inUv); }
