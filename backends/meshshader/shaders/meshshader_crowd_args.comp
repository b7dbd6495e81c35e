#version 450
// meshshader crowd: the task-shader commands of every list from the counts
// the culling pass (crowd_cull.comp) appended, inside crowd.cull. The
// shared culling writes indexed draw commands (the other compute backend
// draws them as they are); a mesh-task draw needs workgroup counts, which
// no word of those commands holds. MS_CLUSTER_ARGS: the cluster lists'
// mesh-only commands from their counts (meshshader_crowd_cluster.comp).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CrowdInstance.h"
#include "tessera/shaders/CrowdMeshlet.h"

layout(local_size_x = TS_CROWD_LISTS) in;

layout(std430, set = 0, binding = TS_BINDING_CROWD_ARGS) readonly buffer ArgsBlock {
    uint crowdArgs[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_MESH_ARGS) buffer MeshArgsBlock {
    CrowdMeshCommand meshArgs[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_CLUSTER_ARGS) buffer ClusterArgsBlock {
    CrowdMeshCommand clusterArgs[];
};

void main() {
    uint list = gl_LocalInvocationID.x;
#ifdef MS_CLUSTER_ARGS
    uint clusters = clusterArgs[list].groups.w;
    uint rows = (clusters + TS_CROWD_TASK_ROW - 1u) / TS_CROWD_TASK_ROW;
    // Rows as even as they go, so the last row leaves fewer than `rows`
    // workgroups with nothing to draw.
    clusterArgs[list].groups.xyz = clusters == 0u ? uvec3(0u) : uvec3((clusters + rows - 1u) / rows, rows, 1u);
#else
    uint count = crowdArgs[list * TS_CROWD_ARG_DRAW_WORDS + 1u];
    uint w = meshArgs[list].groups.w;
    meshArgs[list].groups = list < TS_CROWD_MAX_CHARACTERS ? tsCrowdMeshCommand(count, w)
                                                           : tsCrowdMeshletCommand(count, w);
    // The cluster lists count afresh each frame.
    clusterArgs[list].groups.w = 0u;
#endif
}
