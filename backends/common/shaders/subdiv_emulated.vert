#version 450
// The emulated backends' (r2vb, streamout) evaluation vertex shader for
// subdivision surfaces: one invocation per pattern vertex of one piece of
// one domain's record (EmulatedDrawSource.h; the record's patch index is the
// domain). tsEmuDomainPoint places the point in the D3D11 rules' fixed
// point, so (u, v) equals hulldomain's gl_TessCoord bit for bit, and the
// rest is hulldomain_subdiv_patch.tese line for line: the same evaluation,
// the same varyings, the same vertices.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "subdiv_eval.glsl"
#include "subdiv_varyings.glsl"
#include "tessera/shaders/TessPattern.h"

layout(set = 0, binding = TS_BINDING_EMU_RECORDS) uniform samplerBuffer records;
layout(push_constant) uniform EmulatedDraw {
    uint capacity; // records the buffer holds; the second half starts here
} draw;

layout(location = 0) in uint inRef;

void main() {
    uint record = uint(gl_InstanceIndex) / TS_EMU_PIECES;
    uint piece = uint(gl_InstanceIndex) % TS_EMU_PIECES;
    vec4 outer = texelFetch(records, int(record));
    vec4 inner = texelFetch(records, int(draw.capacity + record));
    uvec4 outerFxp;
    uvec2 innerFxp;
    tsEmuFixedLevels(outer, inner.xy, outerFxp, innerFxp);
    vec2 uv = tsEmuDomainPoint(inRef, piece, outerFxp, innerFxp);
    uint domain = uint(inner.z);
    TsSubdivVertex v = tsSubdivEvaluate(domain, uv);
    tsSubdivWriteVaryings(domain, v);
}
