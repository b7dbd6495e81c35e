// mesh_patches.glsl: how a task workgroup hands quad patches to mesh
// workgroups, for the meshshader backend's terrain patches and subdivision
// domains alike, and for the GPU test that captures their patterns. A task
// workgroup takes 32 patches; each patch that survives culling asks for one
// mesh workgroup per group of consecutive pieces of its pattern
// (tsMeshPiecesPerGroup: one piece each at high levels, the whole patch in
// one at low levels, where a piece holds a few triangles), and firstGroup (an
// exclusive prefix sum) says which workgroups are whose.
// Task stage: define MS_TASK_STAGE, include TessMeshPattern.h first.
// Mesh stage: include mesh_tess.glsl first and define
// `void msWritePoint(uint vertex, uint patchIndex, vec2 uv)`, which writes
// output vertex `vertex` for domain point `uv` of patch `patchIndex`. The
// GPU capture test defines MS_CAPTURE and the two functions declared under
// it, to see every triangle this code emits.
#ifndef MESH_PATCHES_GLSL
#define MESH_PATCHES_GLSL

#define MS_TASK_PATCHES TS_MESH_TASK_PATCHES

struct PatchTaskPayload {
    vec4 outer[MS_TASK_PATCHES];
    vec2 inner[MS_TASK_PATCHES];
    uint patchIndex[MS_TASK_PATCHES];
    uint firstGroup[MS_TASK_PATCHES + 1u];
};

taskPayloadSharedEXT PatchTaskPayload payload;

#ifdef MS_TASK_STAGE
shared uint msGroups[MS_TASK_PATCHES + 1u];

// Called by every invocation of the task workgroup: `visible` says whether
// this invocation's patch is drawn at all; then its levels say how many
// mesh workgroups. Launches the workgroup's mesh workgroups.
void msEmitPatchPieces(bool visible, uint patchIndex, vec4 outer, vec2 inner) {
    uint lane = gl_LocalInvocationID.x;
    uint count = 0u;
    if (visible) {
        count = tsMeshGroupCount(tsMeshPatch(outer, inner));
        payload.outer[lane] = outer;
        payload.inner[lane] = inner;
        payload.patchIndex[lane] = patchIndex;
    }
    msGroups[lane] = count;
    barrier();
    if (lane == 0u) {
        uint total = 0u;
        for (uint i = 0u; i < MS_TASK_PATCHES; ++i) {
            uint own = msGroups[i];
            payload.firstGroup[i] = total;
            total += own;
        }
        payload.firstGroup[MS_TASK_PATCHES] = total;
        msGroups[MS_TASK_PATCHES] = total;
    }
    barrier();
    EmitMeshTasksEXT(msGroups[MS_TASK_PATCHES], 1u, 1u);
}
#else
void msWritePoint(uint vertex, uint patchIndex, vec2 uv);
#ifdef MS_CAPTURE
void msCaptureTriangle(uvec3 local, uint patchIndex);
void msCaptureDone(uint patchIndex);
#endif

// Draws this mesh workgroup's share: finds its patch (the last slot with
// firstGroup <= the workgroup; patches the task culled own none) and its
// pieces, then writes every point and triangle of them, each piece's after
// the previous one's.
void msDrawPieceGroup() {
    uint id = gl_WorkGroupID.x;
    uint slot = 0u;
    for (uint step = MS_TASK_PATCHES / 2u; step > 0u; step >>= 1u)
        if (payload.firstGroup[slot + step] <= id) slot += step;
    uint patchIndex = payload.patchIndex[slot];
    TsMeshPatch p = tsMeshPatch(payload.outer[slot], payload.inner[slot]);
    uint perGroup = tsMeshPiecesPerGroup(p);
    uint first = (id - payload.firstGroup[slot]) * perGroup;
    uint count = min(perGroup, p.pieceCount - first);
    uint points = 0u, triangles = 0u;
    for (uint i = 0u; i < count; ++i) {
        uvec4 entry = tsMeshPieceEntry(p, first + i);
        points += entry.z + entry.w;
        triangles += entry.y;
    }
    SetMeshOutputsEXT(points, triangles);
    uint vertexBase = 0u, triangleBase = 0u;
    for (uint i = 0u; i < count; ++i) {
        uint piece = first + i;
        uvec4 entry = tsMeshPieceEntry(p, piece);
        uint piecePoints = entry.z + entry.w;
        for (uint v = gl_LocalInvocationID.x; v < piecePoints; v += gl_WorkGroupSize.x)
            msWritePoint(vertexBase + v, patchIndex, tsMeshLocalPoint(p, piece, entry, v));
#ifdef MS_CAPTURE
        barrier(); // the capture reads points other invocations placed
#endif
        for (uint t = gl_LocalInvocationID.x; t < entry.y; t += gl_WorkGroupSize.x) {
            uvec3 local = tsMeshLocalTriangle(entry, t) + uvec3(vertexBase);
            gl_PrimitiveTriangleIndicesEXT[triangleBase + t] = local;
#ifdef MS_CAPTURE
            msCaptureTriangle(local, patchIndex);
#endif
        }
        vertexBase += piecePoints;
        triangleBase += entry.y;
    }
#ifdef MS_CAPTURE
    msCaptureDone(patchIndex);
#endif
}
#endif

#endif
