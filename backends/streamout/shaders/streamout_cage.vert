#version 450
// streamout.cage: the control mesh transformed once per height map (the
// backend re-streams it only after the heights changed). One invocation
// per grid vertex, with no vertex buffer (the vertex ID is the grid point);
// transform feedback captures (world xyz, vertex ID) into the cage buffer,
// which the cull and factor passes then load by ID instead of sampling the
// height map again at every patch corner. The point is terrainSurfacePoint,
// the same as hulldomain's factor pre-pass evaluates, so both backends feed
// the metric the same positions.
#extension GL_GOOGLE_include_directive : require
#include "common_frame.glsl"
#include "terrain_heightmap.glsl"
#define TS_NO_LEVEL_BUFFERS
#include "terrain_tess.glsl"
#include "terrain_metric.glsl"

layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = 16) out vec4 outCage;

void main() {
    uint id = uint(gl_VertexIndex);
    uint side = uint(terrain.tiling.x) + 1u;
    vec2 grid = vec2(float(id % side), float(id / side));
    // IDs stay far below 2^24, so the float holds them exactly.
    outCage = vec4(terrainSurfacePoint(grid), float(id));
    // Nothing is rasterised (rasterizer discard); a point list still needs a size.
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
