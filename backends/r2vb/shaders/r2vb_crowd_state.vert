#version 450
// Pass crowd.state (r2vb): one point per instance of the frame, placed on
// the texel of its id in this frame's R32UI state target (cleared to
// tsLodStateNone(), so an id not drawn this frame ends out of view). The
// point runs the shared LOD rule (tsLodUpdate, CrowdLod.h) against the id's
// state in last frame's target, fetched by texel, and carries the next state.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#define R2VB_CROWD_STATE 1
#include "crowd_common.glsl"
#include "crowd_occluders.glsl"
#include "r2vb_crowd.glsl"

layout(location = 0) flat out uint outState;

void main() {
    CrowdInstance instance = tsCrowdInstance(uint(gl_VertexIndex));
    gl_PointSize = 1.0;
    // The host checked every instance (backend::crowdInstanceValid); this
    // keeps a bad one from landing outside the target all the same.
    if (instance.ids.x >= uCrowd.flags.w || instance.ids.y >= uCrowd.counts.y) {
        outState = tsLodStateNone();
        gl_Position = kR2vbCrowdNowhere;
        return;
    }
    outState = tsLodUpdate(r2vbCrowdState(instance.ids.x), instance.sphere, uCrowd.lod);
    gl_Position = r2vbCrowdTexelPosition(instance.ids.x);
}
