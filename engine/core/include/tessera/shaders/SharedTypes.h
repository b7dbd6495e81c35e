// SharedTypes.h: lets one header declare a layout for both C++ and GLSL.
//
// Layout headers in this folder are included by C++ (host) and by GLSL
// (shaders) alike, so std140/std430 structures are written once and cannot
// drift (OpenSubdiv's patchBasisTypes.h, Falcor's HostDeviceShared.slangh).
// Rules for layouts written with it:
//   - use vec4, uvec4, ivec4 and mat4 members (16-byte aligned in every
//     std140/std430 rule and in C++ with glm), packing scalars into vec4s,
//     or make the whole struct four 4-byte scalars (uint, float: 16 bytes
//     with no padding in either rule, as CrowdListEntry);
//   - follow each struct with TS_CHECK_SIZE(Struct, bytes) (no semicolon: GLSL
//     rejects a stray one), which C++ checks.
// Functions written with TS_INLINE are compiled by both too (crater profile,
// tessellation metrics, patch indexing), so the CPU reference and the shaders
// run the same formula. They may use float, vec2/vec3/vec4, uint and the
// GLSL built-ins named in the using-declarations below; write float literals
// with an f suffix and unsigned ones with u, which both languages accept, and
// declare out-parameters with TS_OUT(type). Integer bit operations (<<, >>,
// &, |) behave alike on uint; >> on int is arithmetic in both (C++20). Round
// with floor(x + 0.5f), not round(): GLSL leaves round()'s .5 direction to
// the implementation.
#ifndef TESSERA_SHARED_TYPES_H
#define TESSERA_SHARED_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace tessera::shader {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
using uvec4 = glm::uvec4;
using ivec3 = glm::ivec3;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
using uint = uint32_t;
using glm::clamp;
using glm::dot;
using glm::floor;
using glm::length;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::sqrt;
using glm::abs;
// Trigonometry for the compressed vertex format. glm::atan(y, x) is
// std::atan2(y, x), the same argument order as GLSL's two-argument atan.
using glm::acos;
using glm::atan;
using glm::cos;
using glm::cross;
using glm::sin;
} // namespace tessera::shader
#define TS_INLINE inline
#define TS_OUT(type) type&
#define TS_NAMESPACE_BEGIN namespace tessera::shader {
#define TS_NAMESPACE_END }
#define TS_CHECK_SIZE(type, bytes) \
    static_assert(sizeof(type) == (bytes), #type " must match its GLSL std140 size"); \
    static_assert(sizeof(type) % 16 == 0, #type " must be a multiple of 16 bytes");
#else
#define TS_NAMESPACE_BEGIN
#define TS_NAMESPACE_END
#define TS_CHECK_SIZE(type, bytes)
#define TS_INLINE
#define TS_OUT(type) out type
#endif

#endif
