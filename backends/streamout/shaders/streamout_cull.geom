#version 450
// streamout.cull, geometry stage: the D3D10 way of culling on the GPU. Each
// patch loads its corners from the cage buffer, tests its displaced bounds
// against the view frustum and streams its index out only if it may be
// visible; the survivors' count lands in the transform-feedback counter,
// which the factor pass's draw-auto reads. The profiler's pipeline
// statistics of this pass show the culling: geometry-shader invocations in,
// primitives out.
//
// The bounds are the patch's x/z extent and the whole height range,
// 0..worldSize.z (the height map is UNORM), so no visible patch is ever
// dropped: the surface between the corners can rise anywhere in that range.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#include "streamout_bindings.h"
#include "streamout_cage.glsl"

layout(points) in;
layout(points, max_vertices = 1) out;

layout(location = 0) in uint vPatch[];
layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 4) out uint outPatch;

// Clip-space outcodes of one point: bit k set when it lies outside plane k
// (x < -w, x > w, y < -w, y > w, z < 0, z > w; Vulkan's depth range). Each
// test is a plane in world space, so a box is outside when all its corners
// share a bit, whatever their w.
uint outcodes(vec3 world) {
    vec4 c = frame.viewProjection * vec4(world, 1.0);
    return uint(c.x < -c.w) | uint(c.x > c.w) << 1u | uint(c.y < -c.w) << 2u | uint(c.y > c.w) << 3u |
           uint(c.z < 0.0) << 4u | uint(c.z > c.w) << 5u;
}

bool outsideFrustum(vec3 lo, vec3 hi) {
    uint outside = 0x3fu;
    for (uint corner = 0u; corner < 8u; ++corner) {
        bvec3 upper = bvec3((corner & 1u) != 0u, (corner & 2u) != 0u, (corner & 4u) != 0u);
        outside &= outcodes(mix(lo, hi, upper));
    }
    return outside != 0u;
}

void main() {
    uint patchIndex = vPatch[0];
    uint patches = uint(terrain.tiling.x);
    uint x = patchIndex % patches;
    uint z = patchIndex / patches;
    vec3 first = soCagePoint(soGridVertex(x, z)).xyz;
    vec3 opposite = soCagePoint(soGridVertex(x + 1u, z + 1u)).xyz;
    vec3 lo = vec3(first.x, 0.0, first.z);
    vec3 hi = vec3(opposite.x, terrain.worldSize.z, opposite.z);
    if (outsideFrustum(lo, hi)) return;
    outPatch = patchIndex;
    EmitVertex();
}
