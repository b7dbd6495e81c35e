#pragma once
// Distance functions the creature's shape is built from (internal header).
// All are approximations that are exact on the surface and close to
// Euclidean near it, which is all that extraction and Newton projection need.

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace tessera::creature::sdf {

/// Polynomial smooth minimum: blends two distances over a band of width k.
inline float smoothMin(float a, float b, float k) {
    if (k <= 0.0f) return std::min(a, b);
    float h = std::max(k - std::abs(a - b), 0.0f) / k;
    return std::min(a, b) - h * h * k * 0.25f;
}

/// Axis-aligned ellipsoid with semi-axes r around the origin; the
/// first-order distance estimate |p/r| - 1 scaled by the local gradient.
inline float ellipsoid(const glm::vec3& p, const glm::vec3& r) {
    float k0 = glm::length(p / r);
    float k1 = glm::length(p / (r * r));
    if (k1 < 1e-9f) return -std::min(r.x, std::min(r.y, r.z));
    return k0 * (k0 - 1.0f) / k1;
}

/// A capsule from a to b whose radius goes linearly from ra to rb.
inline float taperedCapsule(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, float ra, float rb) {
    glm::vec3 ab = b - a;
    float len2 = glm::dot(ab, ab);
    float h = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - a - ab * h) - (ra + (rb - ra) * h);
}

} // namespace tessera::creature::sdf
