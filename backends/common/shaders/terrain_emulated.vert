#version 450
// The evaluation vertex shader behind the emulated tessellator (r2vb and
// streamout): one invocation per pattern vertex of one piece of one
// superprimitive. The pattern buffer gives the point's reference (per vertex),
// the instance index its record (levels and patch) and piece; the point is
// placed with the D3D11 rules in fixed point, so (u, v) equal the hardware's
// gl_TessCoord bit for bit, and then evaluated exactly as hulldomain's domain
// shader does: the patch point, displaced from the height map.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#include "tessera/shaders/TessPattern.h"

layout(set = 0, binding = TS_BINDING_EMU_RECORDS) uniform samplerBuffer records;
layout(push_constant) uniform EmulatedDraw {
    uint capacity; // records the buffer holds; the second half starts here
} draw;

layout(location = 0) in uint inRef;
layout(location = 0) out vec3 outWorld;

void main() {
    uint record = uint(gl_InstanceIndex) / TS_EMU_PIECES;
    uint piece = uint(gl_InstanceIndex) % TS_EMU_PIECES;
    vec4 outer = texelFetch(records, int(record));
    vec4 inner = texelFetch(records, int(draw.capacity + record));
    uvec4 outerFxp;
    uvec2 innerFxp;
    tsEmuFixedLevels(outer, inner.xy, outerFxp, innerFxp);
    vec2 uv = tsEmuDomainPoint(inRef, piece, outerFxp, innerFxp);
    vec2 xz = terrainPatchPoint(uint(inner.z), uv);
    vec3 world = vec3(xz.x, terrainHeight(xz), xz.y);
    outWorld = world;
    gl_Position = frame.viewProjection * vec4(world, 1.0);
}
