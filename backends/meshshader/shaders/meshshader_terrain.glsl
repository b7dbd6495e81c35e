// meshshader_terrain.glsl: what the terrain's task stage hands its mesh
// workgroups. A task workgroup takes 32 visible patches; each patch that
// survives culling asks for one mesh workgroup per piece of its pattern,
// and firstPiece (an exclusive prefix sum) says which workgroups are whose.
#ifndef MESHSHADER_TERRAIN_GLSL
#define MESHSHADER_TERRAIN_GLSL

#define MS_TERRAIN_TASK_PATCHES 32u

struct TerrainTaskPayload {
    vec4 outer[MS_TERRAIN_TASK_PATCHES];
    vec2 inner[MS_TERRAIN_TASK_PATCHES];
    uint patchIndex[MS_TERRAIN_TASK_PATCHES];
    uint firstPiece[MS_TERRAIN_TASK_PATCHES + 1u];
};

#endif
