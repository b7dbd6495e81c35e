#pragma once
/// @file Aabb.h
/// Axis-aligned bounding box, the bounding volume of the scene graph and culling.

#include <cfloat>
#include <glm/glm.hpp>

namespace tessera::scene {

/// An axis-aligned box given by its minimum and maximum corners (inclusive).
///
/// A default-constructed box is empty: min = +FLT_MAX and max = -FLT_MAX, so
/// expanding it by any point or box yields exactly that point or box. Large
/// finite values are used rather than infinities so that arithmetic on an empty
/// box never makes NaN. Aggregate initialisation `Aabb{min, max}` also works.
struct Aabb {
    glm::vec3 min{FLT_MAX};
    glm::vec3 max{-FLT_MAX};

    /// The box that contains nothing; the identity of expand().
    static Aabb empty();
    /// A box from its corners; asserts min <= max on every axis.
    static Aabb fromMinMax(const glm::vec3& min, const glm::vec3& max);

    /// True when min > max on any axis (contains no point).
    bool isEmpty() const;

    /// Grows the box to contain `point`.
    void expand(const glm::vec3& point);
    /// Grows the box to contain `other`; an empty `other` changes nothing.
    void expand(const Aabb& other);

    /// Centre of the box. Meaningless for an empty box.
    glm::vec3 center() const;
    /// Half the size on each axis. Meaningless for an empty box.
    glm::vec3 extents() const;

    /// The tightest axis-aligned box around this box transformed by the affine
    /// matrix `m` (Arvo, Graphics Gems 1990): exact for the eight corners, at a
    /// cost of 9 multiply-min-max pairs. The projective row of `m` is ignored,
    /// so pass model matrices, not projections. Empty stays empty.
    Aabb transformed(const glm::mat4& m) const;

    /// True when `point` lies inside or on the boundary.
    bool contains(const glm::vec3& point) const;
};

} // namespace tessera::scene
