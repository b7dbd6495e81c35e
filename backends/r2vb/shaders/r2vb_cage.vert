#version 450
// Pass r2vb.cage (the first paper's pass 1, Listings 13 and 14): the cage of
// the visible patches is drawn as points, four per patch, and each point
// writes its corner's displaced position and grid vertex ID into one texel of
// the cage target. The factor pass reads them back by vertex texture fetch.
// The patch comes from the per-instance stream of visible patches, the corner
// from the vertex index (the paper precomputes its IDs into the stream, as
// D3D9 had no vertex index; Vulkan gives one).
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#define TS_NO_LEVEL_BUFFERS
#include "terrain_tess.glsl"
#include "terrain_metric.glsl"
#include "r2vb_points.glsl"

layout(location = 0) in uint inPatch; // visible patch index (per instance)

layout(location = 0) flat out vec4 outCorner;

void main() {
    // Round the patch: (0,0), (1,0), (1,1), (0,1).
    uint corner = uint(gl_VertexIndex);
    uvec2 local = uvec2(corner == 1u || corner == 2u ? 1u : 0u, corner >= 2u ? 1u : 0u);
    uint patches = tess.mode.z;
    uvec2 grid = uvec2(inPatch % patches, inPatch / patches) + local;
    // The same surface point the factor pre-pass of hulldomain evaluates, so
    // both backends get the same levels. The ID is exact in a float (below 2^24).
    outCorner = vec4(terrainSurfacePoint(vec2(grid)), float(grid.y * (patches + 1u) + grid.x));
    gl_Position = r2vbTexelPosition(uint(gl_InstanceIndex) * 4u + corner);
    gl_PointSize = 1.0;
}
