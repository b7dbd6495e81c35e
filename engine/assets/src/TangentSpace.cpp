// Normals and tangents for primitives that lack them (declared in MeshConverter.h).
#include "MeshConverter.h"

#include <array>
#include <map>

namespace tessera::assets {

void generateNormals(std::vector<character::CageVertex>& vertices, const std::vector<uint32_t>& indices) {
    // Weld by exact position so vertices split at UV seams get the same normal.
    std::map<std::array<float, 3>, glm::vec3> sums;
    auto key = [&](uint32_t i) {
        const glm::vec3& p = vertices[i].position;
        return std::array<float, 3>{p.x, p.y, p.z};
    };
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        glm::vec3 a = vertices[indices[t]].position, b = vertices[indices[t + 1]].position,
                  c = vertices[indices[t + 2]].position;
        glm::vec3 n = glm::cross(b - a, c - a);  // area-weighted
        for (size_t k = 0; k < 3; ++k) sums[key(indices[t + k])] += n;
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        auto it = sums.find(key(static_cast<uint32_t>(i)));
        glm::vec3 n = it != sums.end() ? it->second : glm::vec3(0.0f);
        vertices[i].normal = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
    }
}

void generateTangents(std::vector<character::CageVertex>& vertices, const std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> tan(vertices.size(), glm::vec3(0.0f)), bitan(vertices.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const auto& v0 = vertices[indices[t]];
        const auto& v1 = vertices[indices[t + 1]];
        const auto& v2 = vertices[indices[t + 2]];
        glm::vec3 e1 = v1.position - v0.position, e2 = v2.position - v0.position;
        glm::vec2 d1 = v1.uv - v0.uv, d2 = v2.uv - v0.uv;
        float det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-20f) continue;
        float r = 1.0f / det;
        glm::vec3 sdir = (e1 * d2.y - e2 * d1.y) * r, tdir = (e2 * d1.x - e1 * d2.x) * r;
        for (size_t k = 0; k < 3; ++k) {
            tan[indices[t + k]] += sdir;
            bitan[indices[t + k]] += tdir;
        }
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        glm::vec3 n = vertices[i].normal;
        glm::vec3 t = tan[i] - n * glm::dot(n, tan[i]);  // Gram-Schmidt
        if (glm::dot(t, t) < 1e-20f) {
            // No usable UVs: any unit vector perpendicular to the normal.
            t = std::abs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0)) : glm::cross(n, glm::vec3(0, 1, 0));
        }
        t = glm::normalize(t);
        float w = glm::dot(glm::cross(n, t), bitan[i]) < 0.0f ? -1.0f : 1.0f;
        vertices[i].tangent = glm::vec4(t, w);
    }
}

} // namespace tessera::assets
