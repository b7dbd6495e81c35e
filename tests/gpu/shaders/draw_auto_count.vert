#version 450
// DrawAuto test, counting: one invocation per vertex drawn, reading the
// captured index as its attribute. Built twice: with DRAW_AUTO_STORES=1 it
// adds itself to its draw's slot of a storage buffer (a count and a sum of
// the indices it read), for devices with vertexPipelineStoresAndAtomics;
// with 0 it stores nothing and the pipeline-statistics query counts it.
layout(location = 0) in uint capturedIndex;

layout(push_constant) uniform Draw {
    uint slot; // which draw of the command buffer this is
} draw;

#if DRAW_AUTO_STORES
layout(std430, binding = 0) buffer Counts {
    uint values[]; // per slot: vertices, sum of their captured indices
} counts;
#endif

void main() {
#if DRAW_AUTO_STORES
    atomicAdd(counts.values[draw.slot * 2u], 1u);
    atomicAdd(counts.values[draw.slot * 2u + 1u], capturedIndex);
#endif
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
