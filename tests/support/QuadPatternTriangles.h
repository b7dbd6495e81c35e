#pragma once
// Quad patches' triangles as sorted lists of domain-point triples, so
// patterns built different ways (Tessellator, the emulated tessellator's
// pieces, the mesh-shader pieces, a GPU capture) compare exactly.
#include "tessera/tessellator/Tessellator.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace tessera::test {

using PatternCorner = std::array<float, 2>;
using PatternTriangle = std::array<PatternCorner, 3>;

/// The same triangle with the same winding always compares equal: rotated
/// so the smallest corner comes first.
inline PatternTriangle canonicalTriangle(PatternTriangle t) {
    const auto first = std::min_element(t.begin(), t.end()) - t.begin();
    std::rotate(t.begin(), t.begin() + first, t.end());
    return t;
}

/// Tessellator's quad fractional_odd pattern for `f`, canonical and sorted.
inline std::vector<PatternTriangle> referenceQuadTriangles(const tessellator::TessFactors& f) {
    using namespace tessellator;
    const TessellatedPatch patch = Tessellator::tessellate(Domain::Quad, Partitioning::FractionalOdd, f);
    std::vector<PatternTriangle> triangles;
    for (size_t i = 0; i < patch.indices.size(); i += 3) {
        PatternTriangle t;
        for (size_t c = 0; c < 3; ++c) t[c] = {patch.uv[patch.indices[i + c]].x, patch.uv[patch.indices[i + c]].y};
        triangles.push_back(canonicalTriangle(t));
    }
    std::sort(triangles.begin(), triangles.end());
    return triangles;
}

/// Levels as "outer a b c d inner e f", for failure messages.
inline std::string describeLevels(const tessellator::TessFactors& f) {
    std::ostringstream os;
    os << "outer " << f.outer[0] << " " << f.outer[1] << " " << f.outer[2] << " " << f.outer[3] << " inner "
       << f.inner[0] << " " << f.inner[1];
    return os.str();
}

} // namespace tessera::test
