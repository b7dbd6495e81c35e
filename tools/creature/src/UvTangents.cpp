#include "UvTangents.h"

#include <cmath>

namespace tessera::creature {

void computeTangents(character::CageMesh& cage) {
    std::vector<glm::vec3> sum(cage.vertices.size(), glm::vec3(0.0f));
    for (size_t t = 0; t < cage.indices.size(); t += 3) {
        const auto& v0 = cage.vertices[cage.indices[t]];
        const auto& v1 = cage.vertices[cage.indices[t + 1]];
        const auto& v2 = cage.vertices[cage.indices[t + 2]];
        glm::vec3 e1 = v1.position - v0.position, e2 = v2.position - v0.position;
        glm::vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
        float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-20f) continue;
        // dP/du scaled by the UV area: larger triangles count for more.
        glm::vec3 tangent = (e1 * d2.y - e2 * d1.y) * (det > 0.0f ? 1.0f : -1.0f);
        for (int k = 0; k < 3; ++k) sum[cage.indices[t + static_cast<size_t>(k)]] += tangent;
    }
    for (size_t i = 0; i < cage.vertices.size(); ++i) {
        auto& v = cage.vertices[i];
        glm::vec3 t = sum[i] - v.normal * glm::dot(v.normal, sum[i]);
        float len = glm::length(t);
        if (len < 1e-12f) {
            glm::vec3 helper = std::abs(v.normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
            t = glm::cross(helper, v.normal);
            len = glm::length(t);
        }
        v.tangent = glm::vec4(t / len, 1.0f);
    }
}

} // namespace tessera::creature
