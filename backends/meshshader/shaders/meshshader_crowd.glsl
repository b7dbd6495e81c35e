// meshshader_crowd.glsl: what a crowd meshlet task workgroup hands its mesh
// workgroups (one per meshlet that survived its culling), and the tables
// both stages read (CrowdMeshlet.h).
#ifndef MESHSHADER_CROWD_GLSL
#define MESHSHADER_CROWD_GLSL
#include "tessera/shaders/CrowdMeshlet.h"

layout(std430, set = 0, binding = TS_BINDING_CROWD_MESHLETS) readonly buffer MeshletBlock {
    CrowdMeshlet crowdMeshlets[];
};

struct CrowdMeshletPayload {
    uint entry;                           // index into crowdLists
    uint meshlets[TS_CROWD_TASK_ITEMS];   // the visible meshlets, compacted
};

#endif
