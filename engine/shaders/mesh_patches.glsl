// mesh_patches.glsl: how a task workgroup hands quad patches to mesh
// workgroups, for the meshshader backend's terrain patches and subdivision
// domains alike, and for the GPU test that captures their patterns. A task workgroup takes 32 patches; each patch that survives
// culling asks for one mesh workgroup per piece of its pattern
// (TessMeshPattern.h), and firstPiece (an exclusive prefix sum) says which
// workgroups are whose. Include after GL_EXT_mesh_shader and
// TessMeshPattern.h.
#ifndef MESH_PATCHES_GLSL
#define MESH_PATCHES_GLSL

#define MS_TASK_PATCHES 32u

struct PatchTaskPayload {
    vec4 outer[MS_TASK_PATCHES];
    vec2 inner[MS_TASK_PATCHES];
    uint patchIndex[MS_TASK_PATCHES];
    uint firstPiece[MS_TASK_PATCHES + 1u];
};

taskPayloadSharedEXT PatchTaskPayload payload;

#ifdef MS_TASK_STAGE
shared uint msPieces[MS_TASK_PATCHES + 1u];

// Called by every invocation of the task workgroup: `visible` says whether
// this invocation's patch is drawn at all; then its levels say how many
// pieces. Launches the workgroup's mesh workgroups.
void msEmitPatchPieces(bool visible, uint patchIndex, vec4 outer, vec2 inner) {
    uint lane = gl_LocalInvocationID.x;
    uint count = 0u;
    if (visible) {
        count = tsMeshPatch(outer, inner).pieceCount;
        payload.outer[lane] = outer;
        payload.inner[lane] = inner;
        payload.patchIndex[lane] = patchIndex;
    }
    msPieces[lane] = count;
    barrier();
    if (lane == 0u) {
        uint total = 0u;
        for (uint i = 0u; i < MS_TASK_PATCHES; ++i) {
            uint own = msPieces[i];
            payload.firstPiece[i] = total;
            total += own;
        }
        payload.firstPiece[MS_TASK_PATCHES] = total;
        msPieces[MS_TASK_PATCHES] = total;
    }
    barrier();
    EmitMeshTasksEXT(msPieces[MS_TASK_PATCHES], 1u, 1u);
}
#else
// In the mesh stage: the patch whose pieces include this workgroup (the last
// with firstPiece <= the workgroup; patches the task culled own none), and
// which of its pieces this is.
uint msPatchSlot(out uint piece) {
    uint group = gl_WorkGroupID.x;
    uint slot = 0u;
    for (uint step = MS_TASK_PATCHES / 2u; step > 0u; step >>= 1u)
        if (payload.firstPiece[slot + step] <= group) slot += step;
    piece = group - payload.firstPiece[slot];
    return slot;
}
#endif

#endif
