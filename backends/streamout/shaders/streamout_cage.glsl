// streamout_cage.glsl: reads the transformed cage that streamout.cage wrote
// through transform feedback, by grid vertex ID (z * (P + 1) + x).
// Needs terrain_heightmap.glsl (for the patch count) and streamout_bindings.h.
#ifndef STREAMOUT_CAGE_GLSL
#define STREAMOUT_CAGE_GLSL

layout(set = 0, binding = SO_BINDING_CAGE) uniform samplerBuffer cage;

uint soGridVertex(uint x, uint z) {
    return z * (uint(terrain.tiling.x) + 1u) + x;
}

// (world xyz of the displaced grid point, its vertex ID as a float).
vec4 soCagePoint(uint gridVertex) {
    return texelFetch(cage, int(gridVertex));
}

#endif
