#version 450
// Pass r2vb.commands: writes the record's two texels and its five
// tessellator commands to seven render targets at once (MRT).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/TessPattern.h"

layout(location = 0) flat in vec4 inOuter;
layout(location = 1) flat in vec4 inInner;
layout(location = 2) flat in uvec4 inCommands[TS_EMU_PIECES];

layout(location = 0) out vec4 outOuter;
layout(location = 1) out vec4 outInner;
layout(location = 2) out uvec4 outCommands[TS_EMU_PIECES];

void main() {
    outOuter = inOuter;
    outInner = inInner;
    for (uint piece = 0u; piece < TS_EMU_PIECES; ++piece) outCommands[piece] = inCommands[piece];
}
