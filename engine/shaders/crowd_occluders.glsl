// crowd_occluders.glsl: the horizon's grid for the shaders that run the
// crowd's selection (tsLodUpdate, CrowdLod.h): cell (i, j) of n per side
// holds the lowest height the terrain is drawn at over it, one R32F texel
// each, row by row (GpuCrowd::occludersView; lod::LodView::occluders on the
// CPU). Included after crowd_common.glsl by the culling and binning passes
// of every backend.
#ifndef CROWD_OCCLUDERS_GLSL
#define CROWD_OCCLUDERS_GLSL

layout(set = 0, binding = TS_BINDING_CROWD_OCCLUDERS) uniform samplerBuffer uCrowdOccluders;

float tsLodOccluderMin(uint i, uint j, uint n) { return texelFetch(uCrowdOccluders, int(j * n + i)).x; }

#endif
