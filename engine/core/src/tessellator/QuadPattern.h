#pragma once
// The quad domain: an outer ring of four edges, concentric inner rectangles
// inset by the two inner levels, and at the centre a point, a row of points
// (even spacing across the narrow axis) or a strip of quads (odd spacing).

#include "PatchFactors.h"

#include "tessera/tessellator/TessellationTypes.h"

#include <cstdint>

namespace tessera::tessellator::detail {

class QuadPattern {
public:
    /// Builds the pattern of a patch that is not culled (see TrianglePattern).
    static TessellatedPatch build(const PatchFactors& factors, bool reverseWinding);
    static uint32_t countTriangles(const PatchFactors& factors);
    static uint32_t countPoints(const PatchFactors& factors);
};

} // namespace tessera::tessellator::detail
