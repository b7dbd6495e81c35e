#pragma once
/// @file Bvh.h
/// A bounding-volume hierarchy over a triangle mesh for the displacement
/// baker's ray casts (binned SAH build, Moller-Trumbore intersection).

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace tessera::creature {

/// One ray-triangle intersection.
struct BvhHit {
    float t = 0.0f;         ///< ray parameter: the hit point is origin + t * direction
    uint32_t triangle = 0;  ///< index into the mesh's triangles (indices / 3)
    float u = 0.0f;         ///< barycentric weight of the triangle's second vertex
    float v = 0.0f;         ///< barycentric weight of the third vertex (first = 1 - u - v)
};

/// Static BVH over an indexed triangle list. Triangles are two-sided.
/// Queries are const and may run from several threads at once.
class Bvh {
public:
    /// Builds over `positions` / `indices` (three per triangle). Takes about a
    /// second for a million triangles on one core.
    Bvh(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);

    /// The hit whose t lies in [tMin, tMax] and is nearest to `tTarget`
    /// (smallest |t - tTarget|; ties go to the lower triangle index, so the
    /// answer never depends on traversal order). `tTarget = tMin` gives the
    /// ordinary closest hit along the ray.
    std::optional<BvhHit> nearestHit(const glm::vec3& origin, const glm::vec3& direction, float tMin,
                                     float tMax, float tTarget) const;

    /// Same query by testing every triangle; the reference for tests.
    std::optional<BvhHit> nearestHitBruteForce(const glm::vec3& origin, const glm::vec3& direction,
                                               float tMin, float tMax, float tTarget) const;

    uint32_t nodeCount() const { return static_cast<uint32_t>(mNodes.size()); }

private:
    struct Node {
        glm::vec3 boundsMin;
        uint32_t firstOrLeft;  ///< first triangle (leaf) or left child (inner; right = left + 1)
        glm::vec3 boundsMax;
        uint32_t count;        ///< triangles in a leaf, 0 for an inner node
    };
    /// A triangle in build order, prepared for Moller-Trumbore.
    struct Triangle {
        glm::vec3 v0, edge1, edge2;
        uint32_t original;
    };

    void build(std::vector<glm::vec3>& centroids, std::vector<glm::vec3>& boxMin,
               std::vector<glm::vec3>& boxMax);
    bool intersectTriangle(const Triangle& tri, const glm::vec3& origin, const glm::vec3& direction,
                           float tMin, float tMax, BvhHit& hit) const;

    std::vector<Node> mNodes;
    std::vector<Triangle> mTriangles;
    std::vector<uint32_t> mOrder;  ///< build-order slot -> original triangle
};

} // namespace tessera::creature
