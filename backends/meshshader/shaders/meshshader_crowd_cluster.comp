#version 460
// meshshader crowd, middle and far tiers, cluster lists (the alternative to
// culling meshlets in the task stage; docs/CROWD.md, "meshshader"): the
// list's (instance, meshlet) items flattened as the task stage takes them,
// dispatched from the same command, each culled by the same test
// (msCrowdMeshletItem); the survivors are appended to the list's cluster
// region, one atomic per workgroup, for a mesh-only draw.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define MS_CROWD_CULL 1
#include "crowd_common.glsl"
#include "meshshader_crowd.glsl"

layout(local_size_x = TS_CROWD_TASK_ITEMS) in;

layout(std430, set = 0, binding = TS_BINDING_CROWD_CLUSTERS) writeonly buffer ClusterBlock {
    uvec2 crowdClusters[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_CLUSTER_ARGS) buffer ClusterArgsBlock {
    CrowdMeshCommand clusterArgs[];
};

shared uint sVisible;
shared uint sBase;

void main() {
    if (gl_LocalInvocationIndex == 0u) sVisible = 0u;
    barrier();
    uvec2 item;
    bool visible = msCrowdMeshletItem(msCrowdMeshletItemIndex(), item);
    uint k = visible ? atomicAdd(sVisible, 1u) : 0u;
    barrier();
    if (gl_LocalInvocationIndex == 0u && sVisible > 0u) sBase = atomicAdd(clusterArgs[draw.list].groups.w, sVisible);
    barrier();
    if (visible) crowdClusters[draw.clusterBase + sBase + k] = item;
}
