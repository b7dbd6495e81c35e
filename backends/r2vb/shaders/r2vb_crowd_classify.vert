#version 450
// Pass crowd.classify (r2vb): one point per instance of the frame, placed on
// its Morton-order texel of the histogram pyramid's base (R2vbCrowdLayout.h),
// writing its tier membership as counts: 1 in its tier's channel, and 1 in
// its previous tier's while it fades (its fading copy). An instance is never
// twice in one tier. It reads its new state from crowd.state's target.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#define R2VB_CROWD_STATE 1
#include "crowd_common.glsl"
#include "r2vb_crowd.glsl"

layout(location = 0) flat out uvec4 outCounts;

void main() {
    uint i = uint(gl_VertexIndex);
    CrowdInstance instance = tsCrowdInstance(i);
    gl_PointSize = 1.0;
    uvec4 counts = uvec4(0u);
    if (instance.ids.x < uCrowd.flags.w && instance.ids.y < uCrowd.counts.y) {
        uint next = r2vbCrowdState(instance.ids.x);
        uint tier = tsLodStateTier(next);
        uint previous = tsLodStatePrevious(next);
        if (tier != TS_LOD_NONE) {
            counts[tier] = 1u;
            if (tsLodStateFade(next) > 0u && previous < TS_LOD_TIERS && previous != tier) counts[previous] = 1u;
        }
    }
    outCounts = counts;
    gl_Position = r2vbCrowdPixelPosition(r2vbMortonDecode(i));
}
