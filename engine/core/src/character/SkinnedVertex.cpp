#include "tessera/character/SkinnedVertex.h"

#include <cassert>

namespace tessera::character {

glm::mat3 cofactorMatrix(const glm::mat3& m) {
    // Columns of the cofactor matrix are cross products of the other two
    // columns: no division, so it stays defined for singular matrices.
    return glm::mat3(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
}

SkinnedVertex skinVertex(const CageVertex& vertex, std::span<const glm::mat4> palette) {
    glm::mat4 blended(0.0f);
    float weightSum = 0.0f;
    for (int i = 0; i < 4; ++i) {
        const float w = vertex.weights[i];
        if (w == 0.0f) continue;
        const size_t joint = vertex.joints[i];
        assert(joint < palette.size());
        blended += palette[joint] * w;
        weightSum += w;
    }
    blended = weightSum > 0.0f ? blended * (1.0f / weightSum) : glm::mat4(1.0f);

    const glm::mat3 linear(blended);
    glm::mat3 normalMatrix = cofactorMatrix(linear);
    if (glm::determinant(linear) < 0.0f) normalMatrix = -normalMatrix;

    SkinnedVertex out;
    out.position = glm::vec3(blended * glm::vec4(vertex.position, 1.0f));
    out.normal = glm::normalize(normalMatrix * vertex.normal);
    out.tangent = glm::vec4(glm::normalize(linear * glm::vec3(vertex.tangent)), vertex.tangent.w);
    out.uv = vertex.uv;
    return out;
}

} // namespace tessera::character
