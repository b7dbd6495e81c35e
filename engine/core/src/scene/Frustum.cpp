#include "tessera/scene/Frustum.h"

namespace tessera::scene {

Frustum Frustum::fromViewProjection(const glm::mat4& viewProj) {
    // A world point p maps to clip = M * p, so clip.x = dot(row0, p) and so on.
    // Each clip-space inequality, e.g. -w <= x, becomes dot(row3 + row0, p) >= 0:
    // a world-space plane whose normal points inward. GLM is column-major, so
    // row r is (M[0][r], M[1][r], M[2][r], M[3][r]).
    auto row = [&](int r) {
        return glm::vec4(viewProj[0][r], viewProj[1][r], viewProj[2][r], viewProj[3][r]);
    };
    const glm::vec4 x = row(0), y = row(1), z = row(2), w = row(3);
    Frustum f;
    f.mPlanes = {w + x, w - x, w + y, w - y,
                 z,      // Vulkan depth: 0 <= z, not OpenGL's -w <= z.
                 w - z};
    for (glm::vec4& plane : f.mPlanes) {
        float length = glm::length(glm::vec3(plane));
        // Normalising makes dot(plane, p) a true signed distance, which the
        // box test below relies on when it compares against the box radius.
        if (length > 0.0f) plane /= length;
    }
    return f;
}

Frustum::Containment Frustum::classify(const Aabb& box) const {
    if (box.isEmpty()) return Containment::Outside;
    const glm::vec3 center = box.center();
    const glm::vec3 extents = box.extents();
    Containment result = Containment::Inside;
    for (const glm::vec4& plane : mPlanes) {
        const glm::vec3 normal(plane);
        // Signed distance of the centre, and the box's "radius" along the
        // normal: the distance from the centre to its farthest corner.
        float distance = glm::dot(normal, center) + plane.w;
        float radius = glm::dot(extents, glm::abs(normal));
        if (distance + radius < 0.0f) return Containment::Outside;
        if (distance - radius < 0.0f) result = Containment::Intersects;
    }
    return result;
}

bool Frustum::intersects(const Aabb& box) const { return classify(box) != Containment::Outside; }

bool Frustum::contains(const glm::vec3& point) const {
    for (const glm::vec4& plane : mPlanes) {
        if (glm::dot(glm::vec3(plane), point) + plane.w < 0.0f) return false;
    }
    return true;
}

} // namespace tessera::scene
