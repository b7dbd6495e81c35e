#version 450
// Pass crowd.args (r2vb): one point per list u = tier * creatures + creature.
// The upload is sorted by creature, so creature c's instances are the range
// [first, first + count) of the pyramid's base and its tier-t list holds the
// tier-t elements ranked rank_t(first) to rank_t(first + count) - 1
// (r2vbPyramidRank). The point writes the list's count (copied over the
// count word of the list's draw in crowd.args()) and the indirect draw that
// extracts the list (VkDrawIndirectCommand: count points, one instance,
// firstVertex = the list's region in the lists target, firstInstance = the
// rank of its first element). The near tier keeps its first nearSlots
// elements: element s is near slot s.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#define R2VB_CROWD_PYRAMID 1
#include "crowd_common.glsl"
#include "r2vb_crowd.glsl"

layout(location = 0) flat out uvec4 outDraw;
layout(location = 1) flat out uint outCount;

void main() {
    uint list = uint(gl_VertexIndex);
    uint creatures = max(uCrowd.counts.y, 1u);
    uint tier = list / creatures;
    uvec2 range = r2vbCrowdRange(list - tier * creatures);
    uint first = r2vbPyramidRank(tier, range.x);
    uint end = r2vbPyramidRank(tier, range.x + range.y);
    if (tier == TS_LOD_NEAR) {
        first = min(first, uCrowd.counts.z);
        end = min(end, uCrowd.counts.z);
    }
    outCount = end - first;
    outDraw = uvec4(end - first, 1u, list * pc.pyramid.w, first);
    gl_PointSize = 1.0;
    gl_Position = r2vbCrowdTexelPosition(list);
}
