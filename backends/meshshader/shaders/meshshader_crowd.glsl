// meshshader_crowd.glsl: the middle and far tiers' meshlets: the tables the
// task and mesh stages read (CrowdMeshlet.h), what a task workgroup hands
// its mesh workgroups, and (MS_CROWD_CULL, the task stage) the per-list push
// constants and the test of one (instance, meshlet) item of a list. Needs
// crowd_common.glsl (TS_CROWD).
#ifndef MESHSHADER_CROWD_GLSL
#define MESHSHADER_CROWD_GLSL
#include "tessera/shaders/CrowdMeshlet.h"

layout(std430, set = 0, binding = TS_BINDING_CROWD_MESHLETS) readonly buffer MeshletBlock {
    CrowdMeshlet crowdMeshlets[];
};

// What a meshlet task workgroup hands its mesh workgroups: one (list entry,
// meshlet) per meshlet that survived its culling, compacted.
struct CrowdMeshletPayload {
    uvec2 items[TS_CROWD_TASK_ITEMS];
};

#ifdef MS_CROWD_CULL
#include "tessera/shaders/ShadowCascades.h"
layout(push_constant) uniform CrowdMeshletDraw {
    uint countWord;    // the list's instance count in crowdArgs
    uint listBase;     // the list's first entry in crowdLists
    uint firstMeshlet; // the mesh's first meshlet
    uint meshletCount;
#ifdef TS_SHADOW_CASTER
    ShadowCasterPush caster; // at TS_SHADOW_CASTER_OFFSET (16), as the mesh stage reads it
#endif
} draw;
// A stage has one push-constant block: the caster's push is this one's.
#define TS_SHADOW_CASTER_PUSH draw.caster
#include "shadow_caster.glsl"
layout(std430, set = 0, binding = TS_BINDING_CROWD_ARGS) readonly buffer ArgsBlock {
    uint crowdArgs[];
};

// Item `item` of the list (instance item / meshletCount, meshlet item %
// meshletCount): whether it exists and may show, and its (list entry,
// meshlet). The command flattened the items (tsCrowdMeshletCommand), so a
// workgroup may span instances.
bool msCrowdMeshletItem(uint item, out uvec2 drawn) {
    uint k = item / max(draw.meshletCount, 1u);
    uint m = item - k * draw.meshletCount;
    drawn = uvec2(draw.listBase + k, draw.firstMeshlet + m);
    if (k >= crowdArgs[draw.countWord]) return false;
#ifdef TS_SHADOW_CASTER
    // A caster may shadow the view from outside it or facing away from the
    // camera: no frustum or normal-cone test against the camera, only the
    // cull per cascade, which launches none of its meshlets.
    return !tsShadowCasterCulled(tsCrowdInstance(crowdLists[drawn.x].instance).sphere);
#else
    CrowdInstance instance = tsCrowdInstance(crowdLists[drawn.x].instance);
    return tsCrowdMeshletVisible(crowdMeshlets[drawn.y], tsCrowdWorld(instance), max(instance.animation.y, 1e-6),
                                 uCrowd.lod);
#endif
}

// The item this invocation tests: the workgroups run in rows of
// TS_CROWD_TASK_ROW (x), TS_CROWD_TASK_ITEMS items each.
uint msCrowdMeshletItemIndex() {
    return (gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x) * TS_CROWD_TASK_ITEMS + gl_LocalInvocationIndex;
}
#endif

#endif
