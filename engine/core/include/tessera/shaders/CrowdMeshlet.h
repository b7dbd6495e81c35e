// CrowdMeshlet.h: the meshshader backend's crowd, host and GLSL alike: the
// middle and far tiers' meshlets and the task-shader commands of every
// tier's list.
//
// At crowd creation each creature's cage (the middle tier) and far mesh are
// cut into meshlets (meshoptimizer, at most TS_CROWD_MESHLET_VERTICES
// vertices and TS_CROWD_MESHLET_TRIANGLES triangles); each meshlet keeps a
// bounding sphere and a normal cone in model space that hold for every
// baked frame of the creature's clips, so a task shader can cull it for any
// instance from the instance's placement alone (tsCrowdMeshletVisible).
//
// Bindings (set 0), after the crowd's (CrowdInstance.h):
//   TS_BINDING_CROWD_MESHLETS (44)          CrowdMeshlet[] of every creature
//   TS_BINDING_CROWD_MESHLET_VERTICES (45)  uint: mesh-local vertex index per meshlet vertex
//   TS_BINDING_CROWD_MESHLET_TRIANGLES (46) uint: three 8-bit meshlet-local indices per triangle
//   TS_BINDING_CROWD_MESH_ARGS (47)         CrowdMeshCommand per list
#ifndef TESSERA_CROWD_MESHLET_H
#define TESSERA_CROWD_MESHLET_H
#include "tessera/shaders/CrowdLod.h"
#include "tessera/shaders/SharedTypes.h"

#define TS_CROWD_MESHLET_VERTICES 64u
#define TS_CROWD_MESHLET_TRIANGLES 124u
/// Cage triangles (near) or (instance, meshlet) items (middle, far) per
/// task workgroup.
#define TS_CROWD_TASK_ITEMS 32u
/// Workgroups per row of a command (the near tier: a list's instances per
/// row, y; the meshlet tiers: workgroups per row, x); rows are the next
/// dimension: the per-dimension limit of vkCmdDrawMeshTasksIndirectEXT is
/// at least 65535.
#define TS_CROWD_TASK_ROW 32768u

TS_NAMESPACE_BEGIN

/// One meshlet (48 bytes).
struct CrowdMeshlet {
    uvec4 range;  // x: first meshlet vertex, y: first meshlet triangle, z: vertices, w: triangles
    vec4 sphere;  // xyz: centre, w: radius (model space, every baked frame inside)
    vec4 cone;    // xyz: axis (model space), w: cutoff, the sine of the normals' half angle (1: never culled)
};
TS_CHECK_SIZE(CrowdMeshlet, 48)

/// One list's task-shader command (16 bytes): xyz is
/// VkDrawMeshTasksIndirectCommandEXT, w fixed at creation. The near tier:
/// (task workgroups per instance, the instances of a row, rows), w the
/// workgroups per instance (cage triangle groups, tsCrowdMeshCommand); the
/// middle and far tiers: (workgroups of a row, rows, 1), w the mesh's
/// meshlets (tsCrowdMeshletCommand); the impostor tier: (mesh workgroups
/// of a row, rows, 1), w 0 (tsCrowdImpostorCommand).
struct CrowdMeshCommand {
    uvec4 groups;
};
TS_CHECK_SIZE(CrowdMeshCommand, 16)

/// The task-shader commands: one per list, then one per middle and far list
/// for its shadow casters (the list's instances over the far mesh's
/// simplified casters' meshlets, lod::LodPolicy::farCasterTriangles).
#define TS_CROWD_MESH_COMMANDS (TS_CROWD_LISTS + 2u * TS_CROWD_MAX_CHARACTERS)
/// The casters' command of list (tier, creature), tier middle or far.
TS_INLINE uint tsCrowdCasterCommand(uint tier, uint c) {
    return TS_CROWD_LISTS + (tier - TS_LOD_MIDDLE) * TS_CROWD_MAX_CHARACTERS + c;
}

/// The command of a list holding `count` instances, each taking
/// `perInstance` task workgroups.
TS_INLINE uvec4 tsCrowdMeshCommand(uint count, uint perInstance) {
    if (count == 0u || perInstance == 0u) return uvec4(0u, 0u, 0u, perInstance);
    return uvec4(perInstance, min(count, TS_CROWD_TASK_ROW), (count + TS_CROWD_TASK_ROW - 1u) / TS_CROWD_TASK_ROW,
                 perInstance);
}

/// The command of a meshlet tier's list holding `count` instances of a mesh
/// of `meshlets` meshlets: its (instance, meshlet) items flattened, 32 to a
/// task workgroup, so a far mesh of two meshlets fills a workgroup with 16
/// instances rather than leaving 30 of its 32 invocations idle.
TS_INLINE uvec4 tsCrowdMeshletCommand(uint count, uint meshlets) {
    const uint groups = (count * meshlets + TS_CROWD_TASK_ITEMS - 1u) / TS_CROWD_TASK_ITEMS;
    if (groups == 0u) return uvec4(0u, 0u, 0u, meshlets);
    return uvec4(min(groups, TS_CROWD_TASK_ROW), (groups + TS_CROWD_TASK_ROW - 1u) / TS_CROWD_TASK_ROW, 1u, meshlets);
}

/// Cards one impostor mesh workgroup emits (4 vertices and 2 triangles
/// each: 128 and 64 per workgroup).
#define TS_CROWD_IMPOSTOR_CARDS 32u

/// The command of an impostor list holding `count` entries: mesh workgroups
/// of TS_CROWD_IMPOSTOR_CARDS entries each, launched with no task stage, in
/// rows of TS_CROWD_TASK_ROW.
TS_INLINE uvec4 tsCrowdImpostorCommand(uint count) {
    const uint groups = (count + TS_CROWD_IMPOSTOR_CARDS - 1u) / TS_CROWD_IMPOSTOR_CARDS;
    if (groups == 0u) return uvec4(0u, 0u, 0u, 0u);
    return uvec4(min(groups, TS_CROWD_TASK_ROW), (groups + TS_CROWD_TASK_ROW - 1u) / TS_CROWD_TASK_ROW, 1u, 0u);
}

/// Whether meshlet `m` of an instance placed by `world` (a rotation times
/// the uniform scale `scale`, then a translation) may show: its sphere
/// meets the frustum and its normal cone does not face wholly away from
/// the eye (meshoptimizer's cone test, on the sphere's centre).
TS_INLINE bool tsCrowdMeshletVisible(CrowdMeshlet m, mat4 world, float scale, CrowdLodParams p) {
    const vec4 c = world * vec4(m.sphere.x, m.sphere.y, m.sphere.z, 1.0f);
    const float radius = m.sphere.w * scale;
    if (!tsLodInFrustum(vec4(c.x, c.y, c.z, radius), p)) return false;
    if (m.cone.w >= 1.0f) return true;
    const vec4 a = world * vec4(m.cone.x, m.cone.y, m.cone.z, 0.0f);
    const vec3 axis = vec3(a.x, a.y, a.z) * (1.0f / scale);
    const vec3 d = vec3(c.x - p.eye.x, c.y - p.eye.y, c.z - p.eye.z);
    return dot(d, axis) < m.cone.w * length(d) + radius;
}

TS_NAMESPACE_END

#define TS_BINDING_CROWD_MESHLETS 44
#define TS_BINDING_CROWD_MESHLET_VERTICES 45
#define TS_BINDING_CROWD_MESHLET_TRIANGLES 46
#define TS_BINDING_CROWD_MESH_ARGS 47

#endif
