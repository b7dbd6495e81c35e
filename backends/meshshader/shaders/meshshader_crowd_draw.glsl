// meshshader_crowd_draw.glsl: the mesh stage of the middle and far tiers,
// one workgroup per meshlet of one instance, whether a task workgroup
// (meshshader_crowd_meshlet.mesh) or a cluster list
// (meshshader_crowd_cluster.mesh) named it. Its vertices come from the baked
// vertex animation exactly as crowd_mesh.vert places them on the other
// backends (crowd_baked_mesh.glsl), its triangles are the meshlet's own (the
// mesh's glTF counter-clockwise ones, in meshoptimizer's order).
#ifndef MESHSHADER_CROWD_DRAW_GLSL
#define MESHSHADER_CROWD_DRAW_GLSL
#include "common_frame.glsl"
#include "crowd_baked_mesh.glsl"
#include "meshshader_crowd.glsl"

layout(local_size_x = 32) in;
layout(triangles, max_vertices = TS_CROWD_MESHLET_VERTICES, max_primitives = TS_CROWD_MESHLET_TRIANGLES) out;

layout(std430, set = 0, binding = TS_BINDING_CROWD_MESHLET_VERTICES) readonly buffer MeshletVertexBlock {
    uint meshletVertices[];
};
layout(std430, set = 0, binding = TS_BINDING_CROWD_MESHLET_TRIANGLES) readonly buffer MeshletTriangleBlock {
    uint meshletTriangles[];
};

layout(location = 0) out vec3 outWorld[];
layout(location = 1) out vec3 outNormal[];
layout(location = 2) out vec3 outTangent[];
layout(location = 3) out vec2 outUv[];
layout(location = 4) flat out vec4 outCrowdLod[];
layout(location = 5) flat out vec4 outCrowdShade[];

// Draws meshlet item.y of list entry item.x.
void msCrowdDrawMeshlet(uvec2 item) {
    CrowdMeshlet meshlet = crowdMeshlets[item.y];
    CrowdListEntry entry = crowdLists[item.x];
    // Middle and far tiers: no near level to compute.
    tsCrowdSelectAtLevel(entry, 1.0);
    CrowdBakedMesh mesh = tsCrowdBakedMesh(entry);
    vec4 crowdLod = tsCrowdFragmentLod();
    vec4 crowdShade = tsCrowdFragmentShade();
    SetMeshOutputsEXT(meshlet.range.z, meshlet.range.w);
    for (uint v = gl_LocalInvocationIndex; v < meshlet.range.z; v += gl_WorkGroupSize.x) {
        CrowdBakedPoint p = tsCrowdBakedPoint(mesh, meshletVertices[meshlet.range.x + v]);
        outWorld[v] = p.world.xyz;
        outNormal[v] = p.normal;
        outTangent[v] = p.tangent;
        outUv[v] = p.uv;
        outCrowdLod[v] = crowdLod;
        outCrowdShade[v] = crowdShade;
        gl_MeshVerticesEXT[v].gl_Position = frame.viewProjection * p.world;
    }
    for (uint t = gl_LocalInvocationIndex; t < meshlet.range.w; t += gl_WorkGroupSize.x) {
        uint packed = meshletTriangles[meshlet.range.y + t];
        gl_PrimitiveTriangleIndicesEXT[t] = uvec3(packed & 0xffu, (packed >> 8u) & 0xffu, (packed >> 16u) & 0xffu);
    }
}

#endif
