// emulated_tess.glsl: the control logic of the emulated fixed-function
// tessellator, for the r2vb and streamout passes that write tessellator
// commands. A command is a VkDrawIndirectCommand that draws one pattern
// piece (TessPattern.h) of one superprimitive record; EmulatedTerrainBackend
// draws them all with one indirect multi-draw.
#ifndef EMULATED_TESS_GLSL
#define EMULATED_TESS_GLSL
#include "tessera/shaders/TessPattern.h"

layout(std140, set = 0, binding = TS_BINDING_EMU_KEYS) uniform EmuKeys {
    TsEmuKeyTable tsEmuKeys;
};

// Command `piece` (0..4) of record `record` with the given levels (already
// clamped to the draw's range): (vertexCount, instanceCount, firstVertex,
// firstInstance). A piece with nothing to draw is all zero.
uvec4 tsEmuCommand(vec4 outer, vec2 inner, uint piece, uint record) {
    uvec4 outerFxp;
    uvec2 innerFxp;
    tsEmuFixedLevels(outer, inner, outerFxp, innerFxp);
    uint key = tsEmuPieceKey(outerFxp, innerFxp, piece);
    if (key == TS_EMU_KEY_NONE) return uvec4(0u);
    uvec4 entry = tsEmuKeys.pieces[key];
    return uvec4(entry.y, 1u, entry.x, record * TS_EMU_PIECES + piece);
}

#endif
