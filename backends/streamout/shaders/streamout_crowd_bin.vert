#version 450
// streamout.crowd.bin, vertex stage: a point per survivor of one creature
// (an indirect draw, its count from the cull pass's or the split's stream
// query); each record goes on to the geometry stage, which decides what the
// tier's list (or the mesh survivors) gets.
layout(location = 0) in uvec2 inSurvivor; // (instance, next state)
layout(location = 0) out uvec2 vSurvivor;

void main() {
    vSurvivor = inSurvivor;
}
