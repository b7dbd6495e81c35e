#pragma once
// Charts, flattening and packing of the cage's texture atlas (internal header).

#include "IndexedMesh.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// The cage with its vertices split along chart seams.
struct UvAtlas {
    std::vector<uint32_t> source;   ///< per split vertex: its vertex in the welded mesh
    std::vector<glm::vec2> uvs;     ///< per split vertex, in [0, 1]
    std::vector<uint32_t> indices;  ///< the welded mesh's triangles over the split vertices
    uint32_t chartCount = 0;
};

/// Segments `mesh` into charts whose triangles all face one of the six axis
/// directions (so the planar projection along it never flips a triangle),
/// projects each with a basis that keeps the triangles counter-clockwise in
/// UV (no mirrored charts: tangent w = +1), turns it to its smallest
/// bounding box, and shelf-packs the boxes into [0, 1]^2 at one common
/// texel density with `gutter` UV units around every box.
UvAtlas buildUvAtlas(const IndexedMesh& mesh, float gutter);

} // namespace tessera::creature
