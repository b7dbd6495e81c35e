// mesh_tess.glsl: the mesh-shader tessellator's tables and the work of one
// piece (TessMeshPattern.h): which key it draws and each of its points and
// triangles. The meshshader backend's terrain mesh shader and the GPU test
// that captures its patterns both call these, so the test checks the
// backend's own code.
#ifndef MESH_TESS_GLSL
#define MESH_TESS_GLSL
#include "tessera/shaders/TessMeshPattern.h"

layout(std430, set = 0, binding = TS_BINDING_MESH_KEYS) readonly buffer MeshKeys {
    TsMeshKey tsMeshKeys[];
};
layout(std430, set = 0, binding = TS_BINDING_MESH_TRIANGLES) readonly buffer MeshTriangles {
    uint tsMeshTriangles[];
};

// The key table's entry of piece `piece`: first triangle, triangle count,
// points of row A, points of row B.
uvec4 tsMeshPieceEntry(TsMeshPatch p, uint piece) {
    return tsMeshKeys[tsMeshPieceKey(p, piece)].entry;
}

// Domain point of the piece's local point `local` (row A first, then row B).
vec2 tsMeshLocalPoint(TsMeshPatch p, uint piece, uvec4 entry, uint local) {
    uint row = local < entry.z ? 0u : 1u;
    return tsMeshPiecePoint(p, piece, row, local - row * entry.z);
}

// Local point indices of triangle `t` of the piece.
uvec3 tsMeshLocalTriangle(uvec4 entry, uint t) {
    uint packed = tsMeshTriangles[entry.x + t];
    return uvec3(packed & 0xffu, (packed >> 8u) & 0xffu, (packed >> 16u) & 0xffu);
}

#endif
