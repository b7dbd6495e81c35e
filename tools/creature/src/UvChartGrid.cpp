#include "UvChartGrid.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

namespace {

// Separating axes: the interiors are disjoint if the two triangles'
// projections onto some edge normal at most touch.
bool interiorsOverlap(const UvChartGrid::Triangle& a, const UvChartGrid::Triangle& b) {
    for (const auto* tri : {&a, &b}) {
        for (int k = 0; k < 3; ++k) {
            glm::vec2 e = (*tri)[(k + 1) % 3] - (*tri)[k];
            glm::vec2 axis(-e.y, e.x);
            float scale = glm::dot(axis, axis);
            float eps = 1e-6f * scale;
            float minA = 1e30f, maxA = -1e30f, minB = 1e30f, maxB = -1e30f;
            for (const glm::vec2& p : a) {
                float d = glm::dot(p - (*tri)[k], axis);
                minA = std::min(minA, d);
                maxA = std::max(maxA, d);
            }
            for (const glm::vec2& p : b) {
                float d = glm::dot(p - (*tri)[k], axis);
                minB = std::min(minB, d);
                maxB = std::max(maxB, d);
            }
            if (maxA <= minB + eps || maxB <= minA + eps) return false;
        }
    }
    return true;
}

} // namespace

template <class Visit>
void UvChartGrid::forCells(const Triangle& tri, const Visit& visit) const {
    glm::vec2 lo = glm::min(tri[0], glm::min(tri[1], tri[2])), hi = glm::max(tri[0], glm::max(tri[1], tri[2]));
    auto x0 = static_cast<int32_t>(std::floor(lo.x / mCell)), x1 = static_cast<int32_t>(std::floor(hi.x / mCell));
    auto y0 = static_cast<int32_t>(std::floor(lo.y / mCell)), y1 = static_cast<int32_t>(std::floor(hi.y / mCell));
    for (int32_t y = y0; y <= y1; ++y)
        for (int32_t x = x0; x <= x1; ++x)
            visit((static_cast<uint64_t>(static_cast<uint32_t>(x)) << 32) | static_cast<uint32_t>(y));
}

bool UvChartGrid::overlaps(const Triangle& tri) const {
    bool found = false;
    forCells(tri, [&](uint64_t key) {
        if (found) return;
        auto it = mBuckets.find(key);
        if (it == mBuckets.end()) return;
        for (uint32_t other : it->second)
            if (interiorsOverlap(tri, mTriangles[other])) {
                found = true;
                return;
            }
    });
    return found;
}

void UvChartGrid::add(const Triangle& tri) {
    auto id = static_cast<uint32_t>(mTriangles.size());
    mTriangles.push_back(tri);
    forCells(tri, [&](uint64_t key) { mBuckets[key].push_back(id); });
}

} // namespace tessera::creature
