// shadow_caster.glsl: the clip position of a caster's world point, from the
// camera or, in a stage's depth-only variant (TS_SHADOW_CASTER, docs/LOOKS.md
// "Cascaded shadow maps"), from the sun through the cascade being drawn,
// whose matrix the pass pushes per layer. The stage that writes gl_Position
// calls tsClipPosition, so each backend's caster is its own draw over its
// own lists with only this line changed.
#ifndef SHADOW_CASTER_GLSL
#define SHADOW_CASTER_GLSL
#include "common_frame.glsl"

#ifdef TS_SHADOW_CASTER
// Where the matrix lies in the push constants: after the task stage's own
// on meshshader (TS_SHADOW_CASTER_OFFSET=16), else first.
#ifndef TS_SHADOW_CASTER_OFFSET
#define TS_SHADOW_CASTER_OFFSET 0
#endif
layout(push_constant) uniform ShadowCasterBlock {
    layout(offset = TS_SHADOW_CASTER_OFFSET) mat4 viewProjection; // world to the cascade's clip space
} uShadowCaster;

vec4 tsClipPosition(vec4 world) { return uShadowCaster.viewProjection * world; }
#else
vec4 tsClipPosition(vec4 world) { return frame.viewProjection * world; }
#endif

#endif
