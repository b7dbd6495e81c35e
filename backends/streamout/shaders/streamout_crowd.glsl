// streamout_crowd.glsl: what streamout's crowd culling and binning passes
// share: their push constants and where an instance id's LOD state lives in
// the state render target (one R32UI texel per id, row-major).
#ifndef STREAMOUT_CROWD_GLSL
#define STREAMOUT_CROWD_GLSL

// x: the tier a bin pass sorts into, y: the creature of a per-creature pass,
// z: that creature's first vertex in the pass's cage texels, w: unused.
layout(push_constant) uniform StreamoutCrowdPush {
    uvec4 soCrowd;
};

// The state texel of instance id `id` in a target `width` texels wide.
ivec2 soStatePixel(uint id, uint width) {
    return ivec2(int(id % width), int(id / width));
}

// The clip-space centre of that texel: a point of size 1 drawn there covers
// it alone, so rasterising the point writes the id's state (a D3D10 GPU's
// only scatter).
vec4 soStatePosition(ivec2 pixel, ivec2 size) {
    return vec4((vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0, 0.0, 1.0);
}

#endif
