// subdiv_varyings.glsl: what every backend's evaluation stage (TS_SUBDIV_MESH:
// meshshader's mesh stage) hands the subdivision fragment shader (subdiv.frag): the displaced point, the
// shading frame of its own domain and its level, so the fragment shader
// computes the displaced normal per pixel (the second paper, section 5.3).
#ifndef SUBDIV_VARYINGS_GLSL
#define SUBDIV_VARYINGS_GLSL

#ifdef TS_SUBDIV_FRAGMENT
#define TS_SUBDIV_VARYING in
#else
#define TS_SUBDIV_VARYING out
#endif
// A mesh shader writes every vertex of its workgroup: the outputs are arrays.
#ifdef TS_SUBDIV_MESH
#define TS_SUBDIV_ARRAY []
#else
#define TS_SUBDIV_ARRAY
#endif
layout(location = 0) TS_SUBDIV_VARYING vec3 ioWorld TS_SUBDIV_ARRAY;
layout(location = 1) TS_SUBDIV_VARYING vec3 ioDu TS_SUBDIV_ARRAY;
layout(location = 2) TS_SUBDIV_VARYING vec3 ioDv TS_SUBDIV_ARRAY;
layout(location = 3) TS_SUBDIV_VARYING vec3 ioNu TS_SUBDIV_ARRAY;
layout(location = 4) TS_SUBDIV_VARYING vec3 ioNv TS_SUBDIV_ARRAY;
layout(location = 5) TS_SUBDIV_VARYING vec4 ioUvLevel TS_SUBDIV_ARRAY; // ptex (u, v), level, extraordinary blend
layout(location = 6) flat TS_SUBDIV_VARYING uint ioDomain TS_SUBDIV_ARRAY;

#if defined(TS_SUBDIV_MESH)
// The mesh stage's version: vertex `vertex` of the workgroup's outputs.
void tsSubdivWriteMeshVaryings(uint vertex, uint domain, TsSubdivVertex v) {
    vec4 world = subdiv.model * vec4(v.position, 1.0);
    ioWorld[vertex] = world.xyz;
    ioDu[vertex] = v.du;
    ioDv[vertex] = v.dv;
    ioNu[vertex] = v.nu;
    ioNv[vertex] = v.nv;
    ioUvLevel[vertex] = vec4(v.ptexUv, v.level, v.evBlend);
    ioDomain[vertex] = domain;
    gl_MeshVerticesEXT[vertex].gl_Position = frame.viewProjection * world;
}
#elif !defined(TS_SUBDIV_FRAGMENT)
void tsSubdivWriteVaryings(uint domain, TsSubdivVertex v) {
    vec4 world = subdiv.model * vec4(v.position, 1.0);
    ioWorld = world.xyz;
    ioDu = v.du;
    ioDv = v.dv;
    ioNu = v.nu;
    ioNv = v.nv;
    ioUvLevel = vec4(v.ptexUv, v.level, v.evBlend);
    ioDomain = domain;
    gl_Position = frame.viewProjection * world;
}
#else
TsSubdivVertex tsSubdivReadVaryings() {
    TsSubdivVertex v;
    v.position = vec3(0.0);
    v.du = ioDu;
    v.dv = ioDv;
    v.nu = ioNu;
    v.nv = ioNv;
    v.ptexUv = ioUvLevel.xy;
    v.level = ioUvLevel.z;
    v.evBlend = ioUvLevel.w;
    return v;
}
#endif

#endif
