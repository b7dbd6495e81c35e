#version 450
// streamout.crowd.cull, vertex stage: every instance of one creature is a
// point (firstVertex: the creature's range in the frame's creature-sorted
// instances). It loads the instance (a texel buffer, D3D10's Buffer.Load)
// and last frame's state of its id (Texture2D.Load from the state render
// target), runs the shared rule (tsLodUpdate, CrowdLod.h) and hands the
// survivor record (instance, next state) to the geometry
// stage, placed on the id's texel of this frame's state target.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_samplerless_texture_functions : require
#define TS_CROWD 1
#define TS_CROWD_TEXELS 1
#include "crowd_common.glsl"
#include "crowd_occluders.glsl"
#include "streamout_crowd.glsl"

layout(set = 0, binding = TS_BINDING_CROWD_STATE) uniform utexture2D uState; // last frame's state per id

layout(location = 0) flat out uvec2 vSurvivor;

void main() {
    uint i = uint(gl_VertexIndex);
    CrowdInstance instance = tsCrowdInstance(i);
    ivec2 size = textureSize(uState, 0);
    uint id = instance.ids.x;
    uint next = tsLodStateNone();
    // The host checked every instance (backend::crowdInstanceValid); this
    // keeps a bad one from reading past the state all the same.
    if (id < uCrowd.flags.w && instance.ids.y < uCrowd.counts.y) {
        ivec2 pixel = soStatePixel(id, uint(size.x));
        next = tsLodUpdate(texelFetch(uState, pixel, 0).x, instance.sphere, uCrowd.lod);
        gl_Position = soStatePosition(pixel, size);
    } else {
        gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    }
    vSurvivor = uvec2(i, next);
}
