#pragma once
// The triangle domain: an outer ring of three edges, concentric inner rings
// inset by the inner level, and a centre point (even) or triangle (odd).

#include "PatchFactors.h"

#include "tessera/tessellator/TessellationTypes.h"

#include <cstdint>

namespace tessera::tessellator::detail {

class TrianglePattern {
public:
    /// Builds the pattern of a patch that is not culled (callers check); the
    /// minimal case (all levels 1) is built here too.
    static TessellatedPatch build(const PatchFactors& factors, bool reverseWinding);
    static uint32_t countTriangles(const PatchFactors& factors);
    static uint32_t countPoints(const PatchFactors& factors);
};

} // namespace tessera::tessellator::detail
