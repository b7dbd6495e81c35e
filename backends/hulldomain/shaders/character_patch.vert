#version 450
// hulldomain control points: one invocation per cage vertex (indexed draw,
// so the post-transform cache runs it once per vertex, not per triangle).
// Two-pass: fetches the animated vertex once, a single 128-bit load, and
// decompresses it. Single-pass: hands the index on; the evaluation stage
// skins every tessellated vertex itself.
#extension GL_GOOGLE_include_directive : require
#include "character_common.glsl"

#ifdef TS_SINGLE_PASS
layout(location = 0) out uint outIndex;
void main() {
    outIndex = uint(gl_VertexIndex);
}
#else
layout(std430, set = 0, binding = TS_BINDING_COMPRESSED) readonly buffer CompressedBlock {
    uvec4 compressed[];
};
layout(location = 0) out vec3 outPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec3 outTangent;
layout(location = 3) out vec2 outUv;
void main() {
    CageSample s = tsDecompressCageSample(compressed[gl_VertexIndex]);
    outPosition = s.position;
    outNormal = s.normal;
    outTangent = s.tangent;
    outUv = s.uv;
}
#endif
