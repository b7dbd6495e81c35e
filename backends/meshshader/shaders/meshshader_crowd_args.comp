#version 450
// meshshader crowd: the task-shader commands of every list from the counts
// the culling pass (crowd_cull.comp) appended, inside crowd.cull. The
// shared culling writes indexed draw commands (the other compute backend
// draws them as they are); a mesh-task draw needs workgroup counts, which
// no word of those commands holds.
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CrowdInstance.h"
#include "tessera/shaders/CrowdMeshlet.h"

layout(local_size_x = TS_CROWD_MESH_COMMANDS) in;

layout(std430, set = 0, binding = TS_BINDING_CROWD_ARGS) readonly buffer ArgsBlock {
    uint crowdArgs[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_MESH_ARGS) buffer MeshArgsBlock {
    CrowdMeshCommand meshArgs[];
};

void main() {
    uint command = gl_LocalInvocationID.x;
    // A caster's command counts its list (the middle's, then the far's).
    uint list = command < TS_CROWD_LISTS ? command : TS_LOD_MIDDLE * TS_CROWD_MAX_CHARACTERS + (command - TS_CROWD_LISTS);
    uint count = crowdArgs[list * TS_CROWD_ARG_DRAW_WORDS + 1u];
    uint w = meshArgs[command].groups.w;
    uint tier = list / TS_CROWD_MAX_CHARACTERS;
    if (tier == TS_LOD_NEAR)
        meshArgs[command].groups = tsCrowdMeshCommand(count, w);
    else if (tier == TS_LOD_IMPOSTOR)
        meshArgs[command].groups = tsCrowdImpostorCommand(count); // cards, no task stage
    else
        meshArgs[command].groups = tsCrowdMeshletCommand(count, w);
}
