#version 450
// The overlay's vertices: pixel positions, font-atlas UVs and packed RGBA8
// colours, as Dear ImGui writes them (gpu::UiVertex).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/UiConstants.h"

layout(push_constant) uniform Push { UiConstants ui; };

layout(location = 0) in vec2 inPosition;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec4 inColor;

layout(location = 0) out vec2 outUv;
layout(location = 1) out vec4 outColor;

void main() {
    outUv = inUv;
    outColor = inColor;
    gl_Position = vec4(inPosition * ui.transform.xy + ui.transform.zw, 0.0, 1.0);
}
