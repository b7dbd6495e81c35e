// shadow_caster.glsl: the clip position of a caster's world point, from the
// camera or, in a stage's depth-only variant (TS_SHADOW_CASTER, docs/LOOKS.md
// "Cascaded shadow maps"), from the sun through the cascade being drawn,
// whose matrix the pass pushes per layer. The stage that writes gl_Position
// calls tsClipPosition, so each backend's caster is its own draw over its
// own lists with only this line changed; and, first, tsShadowCasterCulled
// on its instance's bounding sphere: the cull per cascade, which in the
// caster variant skips the instance (every vertex of it outside the clip
// volume, or the meshlet not launched) where neither it nor its shadow
// reaches the cascade's slice, and in the main pass is false.
#ifndef SHADOW_CASTER_GLSL
#define SHADOW_CASTER_GLSL
#include "common_frame.glsl"
#include "tessera/shaders/ShadowCascades.h"

#ifdef TS_SHADOW_CASTER
// Where the push lies in the push constants: after the task stage's own
// on meshshader (TS_SHADOW_CASTER_OFFSET=16), else first.
#ifndef TS_SHADOW_CASTER_OFFSET
#define TS_SHADOW_CASTER_OFFSET 0
#endif
// A stage with a push-constant block of its own (meshshader's meshlet task
// stage) declares the push in it and names it TS_SHADOW_CASTER_PUSH.
#ifndef TS_SHADOW_CASTER_PUSH
layout(push_constant) uniform ShadowCasterBlock {
    layout(offset = TS_SHADOW_CASTER_OFFSET) ShadowCasterPush push; // the cascade being drawn
} uShadowCaster;
#define TS_SHADOW_CASTER_PUSH uShadowCaster.push
#endif

vec4 tsClipPosition(vec4 world) { return TS_SHADOW_CASTER_PUSH.viewProjection * world; }
bool tsShadowCasterCulled(vec4 sphere) {
    float viewDepth = -(frame.view * vec4(sphere.xyz, 1.0)).z;
    return tsShadowCasterOutside(sphere, viewDepth, TS_SHADOW_CASTER_PUSH.viewProjection, TS_SHADOW_CASTER_PUSH.cull);
}
#else
vec4 tsClipPosition(vec4 world) { return frame.viewProjection * world; }
bool tsShadowCasterCulled(vec4 sphere) { return false; }
#endif

// Where a culled caster's vertices go: one point beyond the clip volume's
// right side, so its triangles are dropped before rasterization.
vec4 tsCulledPosition() { return vec4(2.0, 0.0, 0.5, 1.0); }

#endif
