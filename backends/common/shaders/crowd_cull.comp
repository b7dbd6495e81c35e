#version 450
// Crowd culling and LOD binning in compute (hulldomain, meshshader;
// ComputeCrowdCullPass): one invocation per instance runs the shared rule
// (tsLodUpdate, CrowdLod.h) against its state, appends it to its tier's list
// for its creature, and its fading copy to the previous tier's; a near
// instance also takes a compressed-cage slot. The lists' counts are the
// instance counts of the indirect draws that follow, so the CPU never learns
// them and nothing waits on a query.
#extension GL_GOOGLE_include_directive : require
#define TS_CROWD 1
#define TS_CROWD_LISTS_ACCESS writeonly
#include "crowd_common.glsl"
#include "crowd_occluders.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = TS_BINDING_CROWD_STATE) buffer StateBlock {
    uint crowdState[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_ARGS) buffer ArgsBlock {
    uint crowdArgs[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_SLOTS) writeonly buffer SlotBlock {
    uvec2 nearSlots[];
};

void append(uint tier, uint creature, uint instance, float coverage, bool fadingOut) {
    uint slot = 0u;
    if (tier == TS_LOD_NEAR) {
        slot = atomicAdd(crowdArgs[TS_CROWD_ARG_DISPATCH], 1u);
        // The budget keeps the near tier within its slots; a host that
        // asks for more loses the excess rather than reading a wrong cage.
        if (slot >= uCrowd.counts.z) return;
        nearSlots[slot] = uvec2(instance, creature);
    }
    uint list = tier * TS_CROWD_MAX_CHARACTERS + creature;
    uint k = atomicAdd(crowdArgs[list * TS_CROWD_ARG_DRAW_WORDS + 1u], 1u);
    CrowdListEntry entry;
    entry.instance = instance;
    entry.slot = slot;
    entry.coverage = coverage;
    entry.flags = (fadingOut ? 1u : 0u) | (tier << 8u);
    uint first = uCrowd.creatureFirst[creature >> 2u][creature & 3u];
    crowdLists[tsCrowdListBase(tier, first, uCrowd.counts.w) + k] = entry;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uCrowd.counts.x) return;
    CrowdInstance instance = crowdInstances[i];
    // The host checked every instance (backend::crowdInstanceValid); these
    // keep a bad one from reaching past a buffer all the same.
    if (instance.ids.x >= uCrowd.flags.w || instance.ids.y >= uCrowd.counts.y) return;
    uint next = tsLodUpdate(crowdState[instance.ids.x], instance.sphere, uCrowd.lod);
    crowdState[instance.ids.x] = next;
    uint tier = tsLodStateTier(next);
    if (tier == TS_LOD_NONE) return;
    float coverage = tsLodCoverage(next, uCrowd.lod);
    append(tier, instance.ids.y, i, coverage, false);
    if (tsLodStateFade(next) > 0u) append(tsLodStatePrevious(next), instance.ids.y, i, 1.0 - coverage, true);
}
