#pragma once
// Uniform-level triangle patches' triangles as sorted lists of domain-point
// triples (QuadPatternTriangles.h's canonical form), so patterns built
// different ways (Tessellator, the mesh-shader pieces) compare exactly.
#include "QuadPatternTriangles.h"

#include "tessera/tessellator/Tessellator.h"

#include <algorithm>
#include <vector>

namespace tessera::test {

/// Every outer level and the inner level of a triangle set to `level`.
inline tessellator::TessFactors uniformTriangleLevels(float level) {
    return tessellator::TessFactors{{level, level, level, level}, {level, level}};
}

/// Tessellator's triangle fractional_odd pattern at one uniform level,
/// canonical and sorted.
inline std::vector<PatternTriangle> referenceTriangleTriangles(float level) {
    using namespace tessellator;
    const TessellatedPatch patch =
        Tessellator::tessellate(Domain::Triangle, Partitioning::FractionalOdd, uniformTriangleLevels(level));
    std::vector<PatternTriangle> triangles;
    for (size_t i = 0; i < patch.indices.size(); i += 3) {
        PatternTriangle t;
        for (size_t c = 0; c < 3; ++c) t[c] = {patch.uv[patch.indices[i + c]].x, patch.uv[patch.indices[i + c]].y};
        triangles.push_back(canonicalTriangle(t));
    }
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

} // namespace tessera::test
