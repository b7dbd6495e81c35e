#pragma once
// Finds overlaps between flattened triangles of one chart (internal header).

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <unordered_map>
#include <vector>

namespace tessera::creature {

/// The triangles already in a chart, bucketed on a square grid in the
/// chart's plane so a new triangle is tested only against its neighbours.
class UvChartGrid {
public:
    using Triangle = std::array<glm::vec2, 3>;

    /// `cell`: bucket size in the plane's units (about a triangle's size).
    explicit UvChartGrid(float cell) : mCell(cell) {}

    /// True if `tri`'s interior overlaps the interior of a triangle added
    /// before (touching along an edge or at a corner is not overlapping).
    bool overlaps(const Triangle& tri) const;
    /// Adds a triangle.
    void add(const Triangle& tri);

private:
    template <class Visit>
    void forCells(const Triangle& tri, const Visit& visit) const;

    float mCell;
    std::vector<Triangle> mTriangles;
    std::unordered_map<uint64_t, std::vector<uint32_t>> mBuckets;  // looked up only, never iterated
};

} // namespace tessera::creature
