#pragma once
/// @file Region.h
/// An area on the ground (world XZ): where agents spawn and where they go.

#include <glm/vec2.hpp>

namespace tessera::crowd {

/// A disc or an axis-aligned rectangle in world XZ (metres). Goals are
/// regions, never points: an agent has arrived as soon as it stands inside,
/// so a crowd does not deadlock pushing towards one spot (the Froblins'
/// known failure at small goals).
struct Region {
    enum class Shape { Disc, Rect };

    Shape shape = Shape::Disc;
    glm::vec2 center{0.0f};
    /// Disc: x is the radius (y unused). Rect: half the size along X and Z.
    glm::vec2 halfSize{10.0f, 10.0f};

    static Region disc(glm::vec2 center, float radius) { return {Shape::Disc, center, {radius, radius}}; }
    static Region rect(glm::vec2 min, glm::vec2 max) { return {Shape::Rect, 0.5f * (min + max), 0.5f * (max - min)}; }

    /// True when `point` is inside or on the boundary.
    bool contains(glm::vec2 point) const;
    /// Distance from `point` to the region (0 inside), metres.
    float distanceTo(glm::vec2 point) const;
    /// Corners of the bounding rectangle.
    glm::vec2 boundsMin() const { return center - halfSize; }
    glm::vec2 boundsMax() const { return center + halfSize; }
    /// The point at unit-square coordinates (u, v) in [0, 1)^2, mapped so a
    /// uniform (u, v) gives a uniform point of the region.
    glm::vec2 pointAt(float u, float v) const;
    /// True when the size is positive and finite.
    bool valid() const;
};

} // namespace tessera::crowd
