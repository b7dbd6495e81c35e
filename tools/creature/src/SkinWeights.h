#pragma once
// Skin weights for the cage (internal header).

#include "CreatureSdf.h"

#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// Up to four joints and weights for one vertex (weights sum to 1, sorted
/// by decreasing weight, unused slots zero).
struct VertexWeights {
    glm::u16vec4 joints{0};
    glm::vec4 weights{0.0f};
};

/// Weights each position by how close it is to each bone's own shapes in
/// the distance field: the nearest bone dominates and neighbours within a
/// few centimetres blend in smoothly, so joints bend softly. Deterministic;
/// joint indices are Joint values.
std::vector<VertexWeights> computeSkinWeights(const CreatureSdf& sdf, const std::vector<glm::vec3>& positions);

} // namespace tessera::creature
