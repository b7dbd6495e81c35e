#pragma once
/// @file TessellationTypes.h
/// The vocabulary of the emulated fixed-function tessellator: which domain,
/// which spacing, the levels of one patch and the pattern it produces.
///
/// Conventions are Vulkan's (they are also D3D11's, which is what Vulkan
/// implementations such as Mesa's lavapipe run: the levels are handed to the
/// D3D11 reference tessellator unchanged, and its (u, v) come back as
/// gl_TessCoord.xy).

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace tessera::tessellator {

/// The abstract patch being subdivided.
enum class Domain {
    Triangle, ///< barycentric (u, v, w = 1 - u - v), Vulkan `triangles`
    Quad,     ///< unit square (u, v), Vulkan `quads`
};

/// How a level becomes segments along an edge (Vulkan spacing, D3D11 partitioning).
enum class Partitioning {
    Integer,        ///< `equal_spacing`: levels clamped to [1, 64] and rounded up
    FractionalOdd,  ///< `fractional_odd_spacing`: levels clamped to [1, 63]
    FractionalEven, ///< `fractional_even_spacing`: levels clamped to [2, 64]
};

/// The levels of one patch, in the order of gl_TessLevelOuter / gl_TessLevelInner.
///
/// - Triangle: outer[0] subdivides the u = 0 edge, outer[1] the v = 0 edge,
///   outer[2] the w = 0 edge; inner[0] sets the rings. outer[3] and inner[1]
///   are ignored.
/// - Quad: outer[0] subdivides the u = 0 edge, outer[1] v = 0, outer[2] u = 1,
///   outer[3] v = 1; inner[0] sets the columns along u, inner[1] the rows
///   along v.
///
/// A patch with any used outer level <= 0, denormal or NaN is culled (no output).
/// Anything else is clamped to the spacing's range, so any float is valid.
struct TessFactors {
    std::array<float, 4> outer{1.0f, 1.0f, 1.0f, 1.0f};
    std::array<float, 2> inner{1.0f, 1.0f};
};

/// The pattern of one patch: domain points and a triangle list over them.
struct TessellatedPatch {
    /// Domain coordinates, exactly as Vulkan's gl_TessCoord.xy would hold
    /// them (bit-for-bit: every value is a multiple of 2^-16). Quad: (u, v).
    /// Triangle: (u, v) of the barycentric (u, v, 1 - u - v).
    std::vector<glm::vec2> uv;
    /// Three indices into `uv` per triangle. Every triangle has three distinct
    /// indices, but a few may have zero area: the reference tessellator emits
    /// them too (e.g. fractional_odd with an inner level just above 1), and
    /// the hardware counts them as primitives.
    ///
    /// Winding: the order Vulkan produces for `vertex_order_ccw` with the
    /// default upper-left domain origin (VK_TESSELLATION_DOMAIN_ORIGIN_UPPER_LEFT):
    /// counter-clockwise when the domain is drawn with u to the right and v
    /// downwards, i.e. a negative signed area in a v-up (u, v) plot.
    std::vector<uint32_t> indices;

    uint32_t triangleCount() const { return static_cast<uint32_t>(indices.size() / 3); }
};

} // namespace tessera::tessellator
