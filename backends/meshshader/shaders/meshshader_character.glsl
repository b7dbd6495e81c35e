// meshshader_character.glsl: what a character's task workgroup hands its
// mesh workgroups: its first cage triangle and how many it covers; the
// group table (mesh_tess.glsl) says which triangles and pieces workgroup g
// draws (several small patches, or some pieces of one large one);
// in a crowd's near tier (TS_CROWD) also the instance's list entry, its
// level (selected once, by the task workgroup) and its creature's first
// cage index in the crowd's index buffer.
#ifndef MESHSHADER_CHARACTER_GLSL
#define MESHSHADER_CHARACTER_GLSL

#define MS_CHARACTER_TASK_TRIANGLES 32u

struct CharacterTaskPayload {
    uint firstTriangle;
    uint triangles;
#ifdef TS_CROWD
    uint entry;      // index into crowdLists
    float level;     // the instance's near level (tsCrowdSelect)
    uint firstIndex; // the creature's first cage index
#endif
};

#endif
