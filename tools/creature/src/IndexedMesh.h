#pragma once
// A plain indexed triangle mesh used between the generator's stages
// (internal header).

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

struct IndexedMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;  ///< three per triangle, counter-clockwise from outside

    uint32_t triangleCount() const { return static_cast<uint32_t>(indices.size() / 3); }
};

} // namespace tessera::creature
