#pragma once
/// @file BakeRayCaster.h
/// The baker's inner loop: one ray per covered texel from the cage surface
/// to the sculpt, giving a displacement and a tangent-space normal.

#include "UvRasterizer.h"
#include "creature/Bvh.h"
#include "creature/SculptMesh.h"
#include "tessera/character/CageMesh.h"

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// What a texel's ray found.
enum class TexelState : uint8_t { Unbaked, Hit, Miss };

/// Per-texel results of castTexelRays (row-major, `size` x `size`).
struct BakedTexels {
    std::vector<float> displacement;  ///< model-space units along the cage direction
    std::vector<glm::vec3> normal;    ///< the sculpt's normal in the cage's tangent frame
    std::vector<TexelState> state;
    uint64_t misses = 0;
};

/// Area-weighted smooth vertex normals of the sculpt (unit; +Z where a vertex
/// touches only degenerate triangles).
std::vector<glm::vec3> sculptVertexNormals(const SculptMesh& sculpt);

/// Casts, for every texel the rasteriser covers, a ray from the cage point
/// along the normalised interpolated cage normal, keeping the sculpt hit in
/// [-inner, +outer] nearest the cage. Rows are shared among `threads`
/// threads; each texel is computed independently, so the output does not
/// depend on the thread count. `progress` is called on the calling thread.
BakedTexels castTexelRays(const character::CageMesh& cage, const UvRasterizer& raster, const Bvh& bvh,
                          const SculptMesh& sculpt, const std::vector<glm::vec3>& sculptNormals,
                          float inner, float outer, uint32_t threads,
                          const std::function<void(float)>& progress);

} // namespace tessera::creature
