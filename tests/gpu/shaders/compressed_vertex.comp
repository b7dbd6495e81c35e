#version 450
// The compressed vertex format's GLSL half against its C++ half: packs each
// input as the skinning pass would, and unpacks the C++ packing of it as the
// tessellation pass would (tests/gpu/compressed_vertex_test.cpp compares).
#extension GL_GOOGLE_include_directive : require
#include "tessera/shaders/CompressedVertex.h"
#include "../support/CompressedVertexTestLayout.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Inputs {
    TsCvTestInput inputs[];
};
layout(std430, set = 0, binding = 1) writeonly buffer Outputs {
    TsCvTestOutput outputs[];
};
layout(push_constant) uniform Push {
    TsCvTestParams params;
};

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.count.x) return;
    TsCvTestInput v = inputs[i];
    vec3 boxMin = params.boxMin.xyz, boxMax = params.boxMax.xyz;
    vec2 uvMin = params.uvRange.xy, uvMax = params.uvRange.zw;
    TsCvTestOutput o;
    o.gpuWord = tsPackVertex(v.position.xyz, v.normal.xyz, v.tangent.xyz, v.uv.xy, boxMin, boxMax, uvMin, uvMax);
    vec3 position, normal, tangent;
    vec2 uv;
    tsUnpackVertex(v.cpuWord, boxMin, boxMax, uvMin, uvMax, position, normal, tangent, uv);
    o.position = vec4(position, 1.0);
    o.normal = vec4(normal, 0.0);
    o.tangent = vec4(tangent, 0.0);
    o.uv = vec4(uv, 0.0, 0.0);
    outputs[i] = o;
}
