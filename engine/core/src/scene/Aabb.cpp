#include "tessera/scene/Aabb.h"

#include <cassert>

namespace tessera::scene {

Aabb Aabb::empty() { return Aabb{}; }

Aabb Aabb::fromMinMax(const glm::vec3& min, const glm::vec3& max) {
    assert(glm::all(glm::lessThanEqual(min, max)) && "Aabb::fromMinMax: min > max");
    return Aabb{min, max};
}

bool Aabb::isEmpty() const { return glm::any(glm::greaterThan(min, max)); }

void Aabb::expand(const glm::vec3& point) {
    min = glm::min(min, point);
    max = glm::max(max, point);
}

void Aabb::expand(const Aabb& other) {
    // No isEmpty() test needed: an empty box's FLT_MAX/-FLT_MAX corners lose
    // every min/max against real coordinates.
    min = glm::min(min, other.min);
    max = glm::max(max, other.max);
}

glm::vec3 Aabb::center() const { return (min + max) * 0.5f; }

glm::vec3 Aabb::extents() const { return (max - min) * 0.5f; }

Aabb Aabb::transformed(const glm::mat4& m) const {
    if (isEmpty()) return Aabb{};
    // Arvo's method: each output axis i is translation[i] plus, per input axis
    // j, the smaller (for min) or larger (for max) of m[j][i] * min[j] and
    // m[j][i] * max[j]. GLM is column-major, so m[j][i] is row i, column j.
    glm::vec3 outMin(m[3]);
    glm::vec3 outMax(m[3]);
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            float a = m[j][i] * min[j];
            float b = m[j][i] * max[j];
            outMin[i] += glm::min(a, b);
            outMax[i] += glm::max(a, b);
        }
    }
    return Aabb{outMin, outMax};
}

bool Aabb::contains(const glm::vec3& point) const {
    return glm::all(glm::lessThanEqual(min, point)) && glm::all(glm::lessThanEqual(point, max));
}

} // namespace tessera::scene
