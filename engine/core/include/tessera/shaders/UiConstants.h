// UiConstants.h: the overlay's push constants (gpu::UiRenderer, ui.vert):
// pixels to clip space, one scale and offset for the whole draw list.
#ifndef TESSERA_UI_CONSTANTS_H
#define TESSERA_UI_CONSTANTS_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

struct UiConstants {
    vec4 transform; // xy: scale (2 / display size), zw: offset (-1 - origin * scale)
};
TS_CHECK_SIZE(UiConstants, 16)

TS_NAMESPACE_END

#define TS_BINDING_UI_FONT 0

#endif
