#pragma once
/// @file Tessellator.h
/// The emulated fixed-function tessellator: a CPU reference that produces the
/// same domain points and triangles as a Vulkan (D3D11-rule) tessellator.
///
/// It follows the D3D11 reference tessellator, which Mesa's lavapipe runs and
/// which D3D11-class hardware matches:
///  - levels are clamped per partitioning, rounded up for integer spacing, and
///    converted to 16.16 fixed point (round to nearest even);
///  - every edge is built from half a level mirrored about its midpoint, so two
///    patches sharing an edge with the same level get bit-identical points;
///  - fractional levels split points in ruler-function order, and the outer
///    edges are stitched to the first inner ring in that same order;
///  - inner rings are stitched to each other with mirrored diagonals.
/// Used by the r2vb and streamout backends to build their pattern buffers and
/// to count primitives (ComputeNumTessellatedPrimitives in the paper), and by
/// the GPU tests as the reference the device must match.

#include "tessera/tessellator/TessellationTypes.h"

#include <cstdint>

namespace tessera::tessellator {

class Tessellator {
public:
    /// Tessellates one patch. A culled patch (an outer level <= 0, denormal or NaN) gives
    /// an empty pattern. Points are deduplicated only as the reference does:
    /// each index is one tessellator point, and with degenerate levels two
    /// indices may hold the same coordinates.
    static TessellatedPatch tessellate(Domain domain, Partitioning partitioning, const TessFactors& factors);

    /// Number of triangles tessellate() would emit (the paper's
    /// ComputeNumTessellatedPrimitives), computed from the ring structure
    /// without building the pattern. Includes zero-area triangles, as the
    /// hardware's primitive counters do.
    static uint32_t countTriangles(Domain domain, Partitioning partitioning, const TessFactors& factors);

    /// Number of domain points tessellate() would emit (the evaluation-shader
    /// invocations of one patch, before any post-transform cache).
    static uint32_t countPoints(Domain domain, Partitioning partitioning, const TessFactors& factors);
};

} // namespace tessera::tessellator
