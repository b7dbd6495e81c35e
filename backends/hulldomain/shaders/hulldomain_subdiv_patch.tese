#version 450
// hulldomain domain stage for subdivision surfaces: the shared evaluation
// (subdiv_eval.glsl) at gl_TessCoord, which the emulated backends run at
// their emulated tessellator's points.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "subdiv_eval.glsl"
#include "subdiv_varyings.glsl"

layout(quads, fractional_odd_spacing, ccw) in;
layout(location = 0) patch in uint patchDomain;

void main() {
    uint domain = patchDomain;
    TsSubdivVertex v = tsSubdivEvaluate(domain, gl_TessCoord.xy);
    tsSubdivWriteVaryings(domain, v);
}
