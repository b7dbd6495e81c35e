// mesh_capture.glsl: what the capture mesh shaders (mesh_capture_quad.mesh,
// mesh_capture_triangle.mesh) add to the backend's mesh stage: each point
// the workgroup places is kept in shared memory beside its gl_Position, and
// each triangle it emits is folded into its patch's digest
// (MeshCaptureTestLayout.h), which the test compares with Tessellator's.
// Include after GL_EXT_mesh_shader, the output layout and TessMeshPattern.h.
#ifndef MESH_CAPTURE_GLSL
#define MESH_CAPTURE_GLSL
#include "../support/MeshCaptureTestLayout.h"

layout(std430, set = 0, binding = TS_CAPTURE_BINDING_RESULTS) buffer CaptureResults {
    TsMeshCaptureResult captureResults[];
};
layout(std430, set = 0, binding = TS_BINDING_MESH_PATCHES) readonly buffer CapturePatches {
    TsMeshCapturePatch capturePatches[];
};

shared vec2 capturePoints[TS_MESH_MAX_VERTICES];
shared uint captureCount, captureSum, captureXor;

// Call once, before any capturePoint.
void captureBegin() {
    if (gl_LocalInvocationIndex == 0u) {
        captureCount = 0u;
        captureSum = 0u;
        captureXor = 0u;
    }
}

// Point `v` of the piece at domain point `uv`. The position covers the 1x1
// target's one pixel with the unit square, so rasterizing costs nothing and
// every primitive reaches the rasterizer (the primitives query counts it).
void capturePoint(uint v, vec2 uv) {
    capturePoints[v] = uv;
    gl_MeshVerticesEXT[v].gl_Position = vec4(uv * 2.0 - 1.0, 0.5, 1.0);
}

// a before b, lexicographically as floats: the order std::array<float, 2>'s
// operator< gives the CPU's canonicalTriangle (and, for points in [0, 1],
// the order of their bit patterns).
bool captureBefore(vec2 a, vec2 b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// The canonical hashes of a triangle of local points: rotated so the first
// smallest corner comes first, as std::min_element and std::rotate do.
uvec2 captureHash(uvec3 local) {
    vec2 c0 = capturePoints[local.x], c1 = capturePoints[local.y], c2 = capturePoints[local.z];
    vec2 smallest = c0;
    uint first = 0u;
    if (captureBefore(c1, smallest)) {
        smallest = c1;
        first = 1u;
    }
    if (captureBefore(c2, smallest)) first = 2u;
    if (first == 1u) return tsCaptureHashes(c1, c2, c0);
    if (first == 2u) return tsCaptureHashes(c2, c0, c1);
    return tsCaptureHashes(c0, c1, c2);
}

// This invocation's share of the workgroup's digest.
uint captureOwnCount = 0u, captureOwnSum = 0u, captureOwnXor = 0u;

void captureAdd(uvec3 local) {
    uvec2 h = captureHash(local);
    ++captureOwnCount;
    captureOwnSum += h.x;
    captureOwnXor ^= h.y;
}

// Called by every invocation once all triangles are added: folds the
// workgroup's digest into patch `patchIndex`'s, one set of buffer atomics
// per workgroup.
void captureFlush(uint patchIndex) {
    if (captureOwnCount > 0u) {
        atomicAdd(captureCount, captureOwnCount);
        atomicAdd(captureSum, captureOwnSum);
        atomicXor(captureXor, captureOwnXor);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        atomicAdd(captureResults[patchIndex].triangles, captureCount);
        atomicAdd(captureResults[patchIndex].hashSum, captureSum);
        atomicXor(captureResults[patchIndex].hashXor, captureXor);
        atomicAdd(captureResults[patchIndex].workgroups, 1u);
    }
}

// The triangle path (one piece per workgroup): emits the piece's `entry.y`
// triangles (tsMeshLocalTriangle) as the backend does and adds them.
void captureTriangles(uvec4 entry, uint patchIndex) {
    barrier(); // every point in capturePoints, the totals zeroed
    for (uint t = gl_LocalInvocationID.x; t < entry.y; t += gl_WorkGroupSize.x) {
        uvec3 local = tsMeshLocalTriangle(entry, t);
        gl_PrimitiveTriangleIndicesEXT[t] = local;
        captureAdd(local);
    }
    captureFlush(patchIndex);
}

// The quad path: mesh_patches.glsl's hooks (MS_CAPTURE).
#ifdef MS_CAPTURE
void msCaptureTriangle(uvec3 local, uint patchIndex) {
    captureAdd(local);
}

void msCaptureDone(uint patchIndex) {
    captureFlush(patchIndex);
}
#endif

#endif
