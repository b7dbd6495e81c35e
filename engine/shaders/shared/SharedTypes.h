// SharedTypes.h: lets one header declare a layout for both C++ and GLSL.
//
// Layout headers in this folder are included by C++ (host) and by GLSL
// (shaders) alike, so std140/std430 structures are written once and cannot
// drift (OpenSubdiv's patchBasisTypes.h, Falcor's HostDeviceShared.slangh).
// Rules for layouts written with it:
//   - use only vec4, uvec4, ivec4 and mat4 members (16-byte aligned in every
//     std140/std430 rule and in C++ with glm), packing scalars into vec4s;
//   - follow each struct with TS_CHECK_SIZE(Struct, bytes) (no semicolon: GLSL
//     rejects a stray one), which C++ checks.
#ifndef TESSERA_SHARED_TYPES_H
#define TESSERA_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace tessera::shader {
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
using uint = uint32_t;
} // namespace tessera::shader
#define TS_NAMESPACE_BEGIN namespace tessera::shader {
#define TS_NAMESPACE_END }
#define TS_CHECK_SIZE(type, bytes) \
    static_assert(sizeof(type) == (bytes), #type " must match its GLSL std140 size"); \
    static_assert(sizeof(type) % 16 == 0, #type " must be a multiple of 16 bytes");
#else
#define TS_NAMESPACE_BEGIN
#define TS_NAMESPACE_END
#define TS_CHECK_SIZE(type, bytes)
#endif

#endif
