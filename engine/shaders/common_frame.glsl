// common_frame.glsl: the per-frame uniform block, declared from the shared layout.
#ifndef COMMON_FRAME_GLSL
#define COMMON_FRAME_GLSL
#include "tessera/shaders/FrameUniforms.h"

layout(std140, set = 0, binding = TS_BINDING_FRAME) uniform FrameBlock {
    FrameUniforms frame;
};

#endif
