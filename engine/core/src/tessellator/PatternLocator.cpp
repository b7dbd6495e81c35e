#include "tessera/tessellator/PatternLocator.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include <glm/common.hpp>

namespace tessera::tessellator {

PatternLocator::PatternLocator(TessellatedPatch patch) : mPatch(std::move(patch)) {
    const auto& uv = mPatch.uv;
    const auto& idx = mPatch.indices;
    mTriangles.reserve(mPatch.triangleCount());
    for (uint32_t t = 0; t < mPatch.triangleCount(); ++t) {
        Triangle tri;
        tri.corners = {idx[3 * t], idx[3 * t + 1], idx[3 * t + 2]};
        const glm::vec2 a = uv[tri.corners[0]], e1 = uv[tri.corners[1]] - a, e2 = uv[tri.corners[2]] - a;
        const float det = e1.x * e2.y - e1.y * e2.x;
        if (det == 0.0f) continue;
        tri.origin = a;
        tri.inverseRow0 = glm::vec2(e2.y, -e2.x) / det;
        tri.inverseRow1 = glm::vec2(-e1.y, e1.x) / det;
        mTriangles.push_back(tri);
    }
    // About one triangle a cell: a level-n quad pattern is close to an n x n
    // grid of split squares, so a cell's list holds the two or three
    // triangles whose bounds reach into it.
    mCells = std::clamp(uint32_t(std::ceil(std::sqrt(double(mTriangles.size())))), 1u, 128u);
    auto forEachCell = [&](const Triangle& tri, auto&& visit) {
        const glm::vec2 a = uv[tri.corners[0]], b = uv[tri.corners[1]], c = uv[tri.corners[2]];
        const glm::vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
        for (uint32_t y = cellOf(lo.y); y <= cellOf(hi.y); ++y)
            for (uint32_t x = cellOf(lo.x); x <= cellOf(hi.x); ++x) visit(y * mCells + x);
    };
    // Counting sort of (cell, triangle) pairs: count, prefix sum, fill.
    mCellStart.assign(size_t(mCells) * mCells + 1, 0u);
    for (const Triangle& tri : mTriangles) forEachCell(tri, [&](uint32_t cell) { ++mCellStart[cell + 1]; });
    for (size_t c = 1; c < mCellStart.size(); ++c) mCellStart[c] += mCellStart[c - 1];
    mCellTriangles.resize(mCellStart.back());
    std::vector<uint32_t> fill(mCellStart.begin(), mCellStart.end() - 1);
    for (uint32_t t = 0; t < mTriangles.size(); ++t)
        forEachCell(mTriangles[t], [&](uint32_t cell) { mCellTriangles[fill[cell]++] = t; });
}

PatternLocator::Hit PatternLocator::locate(glm::vec2 uv) const {
    assert(!empty());
    uv = glm::clamp(uv, glm::vec2(0.0f), glm::vec2(1.0f));
    const uint32_t cell = cellOf(uv.y) * mCells + cellOf(uv.x);
    Hit best;
    float bestInside = -1e30f;
    // The triangle whose smallest weight is largest: the one holding the
    // point (smallest weight >= 0), or, for a point rounding put outside
    // them all, the nearest.
    for (uint32_t k = mCellStart[cell]; k < mCellStart[cell + 1]; ++k) {
        const Triangle& tri = mTriangles[mCellTriangles[k]];
        const glm::vec2 d = uv - tri.origin;
        const float w1 = tri.inverseRow0.x * d.x + tri.inverseRow0.y * d.y;
        const float w2 = tri.inverseRow1.x * d.x + tri.inverseRow1.y * d.y;
        const glm::vec3 weights(1.0f - w1 - w2, w1, w2);
        const float inside = std::min({weights.x, weights.y, weights.z});
        if (inside > bestInside) {
            bestInside = inside;
            best.corners = tri.corners;
            best.weights = weights;
            if (inside >= 0.0f) break;
        }
    }
    if (bestInside < 0.0f) {
        best.weights = glm::max(best.weights, glm::vec3(0.0f));
        best.weights /= best.weights.x + best.weights.y + best.weights.z;
    }
    return best;
}

} // namespace tessera::tessellator
