#version 450
// streamout.crowd.cull, geometry stage: the Froblins' culling on D3D10. An
// instance out of view, or dropped by the budget, emits nothing: its state
// texel keeps the target's clear value, tsLodStateNone(). A survivor is
// emitted once, and that one vertex does two things: transform feedback
// streams its record into the creature's region of the survivors buffer
// (a stream query counts them for the bin pass's draws), and the rasterizer writes its next state into the id's texel
// (streamout_crowd_state.frag).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CrowdLod.h"

layout(points) in;
layout(points, max_vertices = 1) out;

layout(location = 0) in uvec2 vSurvivor[];
layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 8) flat out uvec2 outSurvivor;

void main() {
    uvec2 survivor = vSurvivor[0]; // (instance, next state)
    if (tsLodStateTier(survivor.y) == TS_LOD_NONE) return;
    outSurvivor = survivor;
    gl_Position = gl_in[0].gl_Position;
    EmitVertex();
}
