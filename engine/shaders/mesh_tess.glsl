// mesh_tess.glsl: the mesh-shader tessellator's tables and the work of one
// piece: which key it draws and each of its points and triangles, for quad
// patches (TessMeshPattern.h: the terrain) and uniform-level triangle
// patches (TessMeshTrianglePattern.h: characters, the crowd's near tier).
// A pipeline binds one domain's tables. The meshshader backend's mesh
// shaders and the GPU test that captures their patterns both call these, so
// the test checks the backend's own code.
#ifndef MESH_TESS_GLSL
#define MESH_TESS_GLSL
#include "tessera/shaders/TessMeshPattern.h"
#include "tessera/shaders/TessMeshTrianglePattern.h"

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

// The same for a uniform-level triangle patch; the point is (u, v, w).
uvec4 tsMeshTrianglePieceEntry(TsMeshTrianglePatch p, uint piece) {
    return tsMeshKeys[tsMeshTrianglePieceKey(p, piece)].entry;
}

vec3 tsMeshTriangleLocalPoint(TsMeshTrianglePatch p, uint piece, uvec4 entry, uint local) {
    uint row = local < entry.z ? 0u : 1u;
    return tsMeshTrianglePiecePoint(p, piece, row, local - row * entry.z);
}

#ifdef MS_TRIANGLE_GROUPS
// The uniform-level triangle patches' group table
// (MeshTrianglePatternLibrary::groups): per point class (x first group
// entry, y groups per patch, z patches per group), then the groups (x first
// piece, y pieces, z points, w triangles).
layout(std430, set = 0, binding = TS_BINDING_MESH_GROUPS) readonly buffer MeshGroups {
    uvec4 tsMeshGroups[];
};

uvec4 tsMeshTriangleClassInfo(TsMeshTrianglePatch p) {
    return tsMeshGroups[p.points / 2u - 1u];
}

// Mesh workgroups for `patches` patches of one class.
uint tsMeshTriangleGroupCount(uvec4 info, uint patches) {
    return info.z > 1u ? (patches + info.z - 1u) / info.z : patches * info.y;
}
#endif

// Local point indices of triangle `t` of the piece.
uvec3 tsMeshLocalTriangle(uvec4 entry, uint t) {
    uint packed = tsMeshTriangles[entry.x + t];
    return uvec3(packed & 0xffu, (packed >> 8u) & 0xffu, (packed >> 16u) & 0xffu);
}

#endif
