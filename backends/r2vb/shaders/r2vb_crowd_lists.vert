#version 450
// Pass crowd.lists (r2vb): the stream compaction. Drawn indirectly by the
// draws crowd.args wrote, one point per list entry: gl_VertexIndex is the
// entry's texel in the lists target (its list's region plus k) and
// gl_InstanceIndex the rank of the list's first element, so the entry is the
// tier's element first + k overall, found by a top-down traversal of the
// histogram pyramid. The point writes the CrowdListEntry of that instance;
// the target's regions are then copied into crowd.lists(), which the middle
// and far draws read as their instance stream (the R2VB step).
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#define R2VB_CROWD_STATE 1
#define R2VB_CROWD_PYRAMID 1
#include "crowd_common.glsl"
#include "r2vb_crowd.glsl"

layout(location = 0) flat out uvec4 outEntry;

void main() {
    uint texel = uint(gl_VertexIndex);
    uint list = texel / pc.pyramid.w;
    uint k = texel - list * pc.pyramid.w;
    uint tier = list / max(uCrowd.counts.y, 1u);
    uint element = uint(gl_InstanceIndex) + k;
    uint i = r2vbPyramidFind(tier, element);
    // A near entry's element is its slot (crowd.nearSlots ranks them alike).
    outEntry = tsCrowdEntryBits(r2vbCrowdEntry(i, tier, tier == TS_LOD_NEAR ? element : 0u));
    gl_PointSize = 1.0;
    gl_Position = r2vbCrowdTexelPosition(texel);
}
