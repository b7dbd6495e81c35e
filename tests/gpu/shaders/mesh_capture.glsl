// mesh_capture.glsl: what the capture mesh shaders (mesh_capture_quad.mesh,
// mesh_capture_triangle.mesh) add to the backend's mesh stage: each point
// the piece places is kept in shared memory beside its gl_Position, and each
// triangle it emits is folded into its patch's digest
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

// Triangle `t` of the piece, emitted as the backend emits it and hashed in
// canonical order: rotated so the first smallest corner comes first, as
// std::min_element and std::rotate do.
uvec2 captureTriangle(uint t, uvec3 local) {
    gl_PrimitiveTriangleIndicesEXT[t] = local;
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

// Called by every invocation once the points are placed: emits the piece's
// `entry.y` triangles (tsMeshLocalTriangle) and adds them to patch
// `patchIndex`'s digest, one set of buffer atomics per workgroup.
void captureTriangles(uvec4 entry, uint patchIndex) {
    barrier(); // every point in capturePoints, the totals zeroed
    uint count = 0u, sum = 0u, xored = 0u;
    for (uint t = gl_LocalInvocationID.x; t < entry.y; t += gl_WorkGroupSize.x) {
        uvec2 h = captureTriangle(t, tsMeshLocalTriangle(entry, t));
        ++count;
        sum += h.x;
        xored ^= h.y;
    }
    if (count > 0u) {
        atomicAdd(captureCount, count);
        atomicAdd(captureSum, sum);
        atomicXor(captureXor, xored);
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        atomicAdd(captureResults[patchIndex].triangles, captureCount);
        atomicAdd(captureResults[patchIndex].hashSum, captureSum);
        atomicXor(captureResults[patchIndex].hashXor, captureXor);
        atomicAdd(captureResults[patchIndex].workgroups, 1u);
    }
}

#endif
