#include "tessera/crowd/Region.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace tessera::crowd {

bool Region::contains(glm::vec2 point) const {
    const glm::vec2 d = point - center;
    if (shape == Shape::Disc) return glm::dot(d, d) <= halfSize.x * halfSize.x;
    return std::abs(d.x) <= halfSize.x && std::abs(d.y) <= halfSize.y;
}

float Region::distanceTo(glm::vec2 point) const {
    const glm::vec2 d = point - center;
    if (shape == Shape::Disc) return std::max(0.0f, glm::length(d) - halfSize.x);
    return glm::length(glm::max(glm::abs(d) - halfSize, glm::vec2(0.0f)));
}

glm::vec2 Region::pointAt(float u, float v) const {
    if (shape == Shape::Rect) return center + halfSize * (2.0f * glm::vec2(u, v) - 1.0f);
    // Square-root radius: uniform over the disc's area.
    const float r = halfSize.x * std::sqrt(u), a = 2.0f * std::numbers::pi_v<float> * v;
    return center + r * glm::vec2(std::cos(a), std::sin(a));
}

bool Region::valid() const {
    const bool sized = shape == Shape::Disc ? halfSize.x > 0.0f : halfSize.x > 0.0f && halfSize.y > 0.0f;
    return sized && std::isfinite(center.x) && std::isfinite(center.y) && std::isfinite(halfSize.x) &&
           std::isfinite(halfSize.y);
}

} // namespace tessera::crowd
