// terrain_tess.glsl: the tessellated terrain's per-draw settings and the
// per-edge and per-patch levels the factor pre-pass writes and the control
// stage reads. Define TS_LEVELS_WRITE before including to write them.
#ifndef TERRAIN_TESS_GLSL
#define TERRAIN_TESS_GLSL
#include "tessera/shaders/TerrainPatches.h"
#include "tessera/shaders/TessFactors.h"

layout(std140, set = 0, binding = TS_BINDING_TESS) uniform TessBlock {
    TerrainTessUniforms tess;
};

// Passes without the level buffers (the emulated backends) define
// TS_NO_LEVEL_BUFFERS before including.
#ifndef TS_NO_LEVEL_BUFFERS
#ifdef TS_LEVELS_WRITE
#define TS_LEVELS_ACCESS writeonly
#else
#define TS_LEVELS_ACCESS readonly
#endif
layout(std430, set = 0, binding = TS_BINDING_EDGE_LEVELS) TS_LEVELS_ACCESS buffer EdgeLevels {
    float edgeLevels[];
};
layout(std430, set = 0, binding = TS_BINDING_PATCH_LEVELS) TS_LEVELS_ACCESS buffer PatchLevels {
    float patchLevels[];
};
#undef TS_LEVELS_ACCESS
#endif

#endif
