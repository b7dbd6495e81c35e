#version 450
// streamout.crowd.bin, vertex stage: a point per survivor of one creature
// (an indirect draw, its count from the cull pass's stream query); each
// record goes on to the geometry stage, which decides what the tier's list
// gets.
layout(location = 0) in uvec4 inSurvivor; // (instance, next state, id, creature)
layout(location = 0) out uvec4 vSurvivor;

void main() {
    vSurvivor = inSurvivor;
}
