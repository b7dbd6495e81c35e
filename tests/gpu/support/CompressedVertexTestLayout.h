// CompressedVertexTestLayout.h: the buffers of the compressed vertex GPU
// round-trip test (tests/gpu/compressed_vertex_test.cpp and
// shaders/compressed_vertex.comp), written once for both languages.
#ifndef TESSERA_COMPRESSED_VERTEX_TEST_LAYOUT_H
#define TESSERA_COMPRESSED_VERTEX_TEST_LAYOUT_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

/// One vertex to pack (xyz / xy used) and the C++ packing of it, which the
/// shader unpacks so decoding is compared on identical words.
struct TsCvTestInput {
    vec4 position;
    vec4 normal;
    vec4 tangent;
    vec4 uv;
    uvec4 cpuWord;
};
TS_CHECK_SIZE(TsCvTestInput, 80)

/// The shader's packing of the input, and its unpacking of cpuWord.
struct TsCvTestOutput {
    uvec4 gpuWord;
    vec4 position;
    vec4 normal;
    vec4 tangent;
    vec4 uv;
};
TS_CHECK_SIZE(TsCvTestOutput, 80)

/// Push constants: the box, the uv range (xy min, zw max) and x = count.
struct TsCvTestParams {
    vec4 boxMin;
    vec4 boxMax;
    vec4 uvRange;
    uvec4 count;
};
TS_CHECK_SIZE(TsCvTestParams, 64)

TS_NAMESPACE_END

#endif
