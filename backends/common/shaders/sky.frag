#version 450
// The analytic daylight sky (sky_atmosphere.glsl) behind everything: the
// fog's colour in the view direction, so fully fogged terrain and the sky
// are the same colour, plus the sun's disc.
#extension GL_GOOGLE_include_directive : require
#include "sky_atmosphere.glsl"

layout(location = 0) in vec4 inFarPoint;
layout(location = 0) out vec4 outColor;

void main() {
    vec3 dir = normalize(inFarPoint.xyz / inFarPoint.w - frame.cameraPosition.xyz);
    outColor = tsOutputColor(tsFogColor(dir) + tsSunDisc(dir));
}
