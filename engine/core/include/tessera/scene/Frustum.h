#pragma once
/// @file Frustum.h
/// View frustum as six planes, for culling bounding boxes on the CPU.

#include "tessera/scene/Aabb.h"

#include <array>
#include <glm/glm.hpp>

namespace tessera::scene {

/// Six normalized planes (a, b, c, d) with normals pointing into the frustum:
/// a point p is on the inner side of a plane when dot(abc, p) + d >= 0.
///
/// Planes are in the space the matrix maps from (world space for a
/// view-projection matrix). Their order, named by the clip-space inequality each
/// one enforces, is: [0] -w <= x, [1] x <= w, [2] -w <= y, [3] y <= w,
/// [4] 0 <= z (near), [5] z <= w (far). With Tessera's Y-flipped projection
/// (see Camera) plane [2] bounds the top of the screen and [3] the bottom.
///
/// A default-constructed frustum has all-zero planes and so contains everything.
class Frustum {
public:
    /// Result of classifying a box against the frustum.
    enum class Containment { Outside, Intersects, Inside };

    /// Extracts the planes from a view-projection matrix (Gribb and Hartmann,
    /// 2001) for Vulkan clip space, where visible points satisfy -w <= x <= w,
    /// -w <= y <= w and 0 <= z <= w (Vulkan's convention, glm::perspectiveRH_ZO). Works for
    /// any projection, perspective or orthographic, including a Y flip.
    static Frustum fromViewProjection(const glm::mat4& viewProj);

    /// Classifies `box`: Outside when it is wholly behind one plane, Inside when
    /// it is wholly in front of all six, Intersects otherwise. Conservative: a
    /// box near a frustum corner that is outside yet behind no single plane is
    /// reported as Intersects. An empty box is Outside.
    Containment classify(const Aabb& box) const;

    /// True unless classify(box) is Outside (so conservative in the same way).
    bool intersects(const Aabb& box) const;

    /// True when `point` is inside or on the boundary of all six planes.
    bool contains(const glm::vec3& point) const;

    /// The six planes, in the order documented on the class.
    const std::array<glm::vec4, 6>& planes() const { return mPlanes; }

private:
    std::array<glm::vec4, 6> mPlanes{};
};

} // namespace tessera::scene
