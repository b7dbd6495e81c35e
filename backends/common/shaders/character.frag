#version 450
// Character shading shared by every backend (character_shading.glsl).
#extension GL_GOOGLE_include_directive : require
#include "character_shading.glsl"

layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(tsShadeCharacter(inWorld, inNormal, inTangent, inUv), 1.0);
}
