// meshshader_character.glsl: what a character's task workgroup hands its
// mesh workgroups: its first cage triangle and the pieces per triangle, so
// workgroup g draws piece g % pieces of triangle firstTriangle + g / pieces.
#ifndef MESHSHADER_CHARACTER_GLSL
#define MESHSHADER_CHARACTER_GLSL

#define MS_CHARACTER_TASK_TRIANGLES 32u

struct CharacterTaskPayload {
    uint firstTriangle;
    uint pieces;
};

#endif
