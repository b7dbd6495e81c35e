#pragma once
/// @file SculptMesh.h
/// The high-resolution "sculpt" a displacement map is baked from: a plain
/// triangle soup in the cage's bind-pose model space.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// Triangles of the detailed surface (1M+ for a generated creature). Only
/// geometry: the baker reads positions and derives normals from triangles.
struct SculptMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;  ///< three per triangle, counter-clockwise seen from outside

    uint32_t triangleCount() const { return static_cast<uint32_t>(indices.size() / 3); }
};

} // namespace tessera::creature
