#include "tessera/crowd/CrowdLayout.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <string>

namespace tessera::crowd {
namespace {

// The largest 4-connected set of walkable cells, as a per-cell mask.
std::vector<uint8_t> largestArea(const NavGrid& grid, uint32_t& size) {
    const uint32_t w = grid.width(), n = grid.cellCount();
    std::vector<uint32_t> label(n, UINT32_MAX);
    std::vector<uint32_t> queue;
    uint32_t best = UINT32_MAX;
    size = 0;
    for (uint32_t seed = 0, next = 0; seed < n; ++seed) {
        if (label[seed] != UINT32_MAX || !std::isfinite(grid.terrainCost(seed))) continue;
        queue.assign(1, seed);
        label[seed] = next;
        for (size_t head = 0; head < queue.size(); ++head) {
            const uint32_t c = queue[head];
            const int32_t i = int32_t(c % w), j = int32_t(c / w);
            const int32_t di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
            for (int e = 0; e < 4; ++e) {
                if (!grid.inGrid(i + di[e], j + dj[e])) continue;
                const uint32_t m = grid.index(uint32_t(i + di[e]), uint32_t(j + dj[e]));
                if (label[m] == UINT32_MAX && std::isfinite(grid.terrainCost(m))) label[m] = next, queue.push_back(m);
            }
        }
        if (queue.size() > size) size = uint32_t(queue.size()), best = next;
        ++next;
    }
    std::vector<uint8_t> mask(n, 0);
    for (uint32_t c = 0; c < n; ++c) mask[c] = label[c] == best && best != UINT32_MAX;
    return mask;
}

// Chamfer distance (cells) from every cell of `mask` to the nearest cell
// outside it (or the grid's edge).
std::vector<float> clearance(const NavGrid& grid, const std::vector<uint8_t>& mask) {
    const int32_t w = int32_t(grid.width()), h = int32_t(grid.height());
    std::vector<float> d(mask.size());
    for (size_t c = 0; c < mask.size(); ++c) d[c] = mask[c] ? 1e9f : 0.0f;
    auto at = [&](int32_t i, int32_t j) { return i < 0 || j < 0 || i >= w || j >= h ? 0.0f : d[size_t(j) * w + i]; };
    constexpr float diagonal = 1.41421356f;
    for (int32_t j = 0; j < h; ++j)
        for (int32_t i = 0; i < w; ++i) {
            float& v = d[size_t(j) * w + i];
            v = std::min({v, at(i - 1, j) + 1.0f, at(i, j - 1) + 1.0f, at(i - 1, j - 1) + diagonal, at(i + 1, j - 1) + diagonal});
        }
    for (int32_t j = h - 1; j >= 0; --j)
        for (int32_t i = w - 1; i >= 0; --i) {
            float& v = d[size_t(j) * w + i];
            v = std::min({v, at(i + 1, j) + 1.0f, at(i, j + 1) + 1.0f, at(i + 1, j + 1) + diagonal, at(i - 1, j + 1) + diagonal});
        }
    return d;
}

// The most open cell of the area within `reach` metres of `target` (ties:
// nearer, then lower index); UINT32_MAX when there is none.
uint32_t mostOpenNear(const NavGrid& grid, const std::vector<uint8_t>& mask, const std::vector<float>& open,
                      glm::vec2 target, float reach) {
    const CellRect cells = grid.cellsTouching(target - reach, target + reach);
    uint32_t best = UINT32_MAX;
    float bestOpen = -1.0f, bestDistance = 0.0f;
    for (int32_t j = cells.j0; j <= cells.j1; ++j)
        for (int32_t i = cells.i0; i <= cells.i1; ++i) {
            const uint32_t c = grid.index(uint32_t(i), uint32_t(j));
            const float distance = glm::distance(grid.cellCenter(uint32_t(i), uint32_t(j)), target);
            if (!mask[c] || distance > reach) continue;
            if (open[c] > bestOpen || (open[c] == bestOpen && distance < bestDistance))
                best = c, bestOpen = open[c], bestDistance = distance;
        }
    return best;
}

} // namespace

Result<CrowdLayout> planCrowdLayout(const NavGrid& grid, const CrowdLayoutRequest& request) {
    uint32_t areaCells = 0;
    const std::vector<uint8_t> mask = largestArea(grid, areaCells);
    const float cellArea = grid.cellSize() * grid.cellSize();
    // A fifth of the densest random packing: room to walk off the spawn.
    const float needed = float(request.agents) * std::numbers::pi_v<float> * request.agentRadius *
                         request.agentRadius / 0.08f;
    if (areaCells == 0) return fail("crowd layout: the terrain has no walkable ground");
    if (float(areaCells) * cellArea < 2.0f * needed)
        return fail("crowd layout: the largest walkable area of the terrain is ", std::to_string(int64_t(float(areaCells) * cellArea)),
                    " square metres; ", std::to_string(request.agents), " agents need about ",
                    std::to_string(int64_t(2.0f * needed)));
    const std::vector<float> open = clearance(grid, mask);
    const glm::vec2 middle = 0.5f * glm::vec2(float(grid.width()), float(grid.height())) * grid.cellSize();
    uint32_t centre = UINT32_MAX;
    for (float reach = 0.15f * std::min(middle.x, middle.y); centre == UINT32_MAX; reach *= 2.0f)
        centre = mostOpenNear(grid, mask, open, middle, reach);
    const glm::vec2 origin = grid.cellCenter(centre % grid.width(), centre / grid.width());

    CrowdLayout layout;
    float radius = std::sqrt(needed / std::numbers::pi_v<float>);
    for (;; radius *= 1.1f) {
        layout.spawn = Region::disc(origin, radius);
        const CellRect cells = grid.cellsTouching(origin - radius, origin + radius);
        uint32_t inside = 0;
        for (int32_t j = cells.j0; j <= cells.j1; ++j)
            for (int32_t i = cells.i0; i <= cells.i1; ++i)
                inside += mask[grid.index(uint32_t(i), uint32_t(j))] &&
                          layout.spawn.contains(grid.cellCenter(uint32_t(i), uint32_t(j)));
        if (float(inside) * cellArea >= needed) break;
    }
    for (uint32_t g = 0; g < request.groups; ++g) {
        const float angle = 2.0f * std::numbers::pi_v<float> * (float(g) + 0.125f) / float(request.groups);
        const glm::vec2 ideal = origin + request.goalDistance * glm::vec2(std::cos(angle), std::sin(angle));
        uint32_t cell = UINT32_MAX;
        for (float reach = 0.25f * request.goalDistance; cell == UINT32_MAX; reach *= 2.0f)
            cell = mostOpenNear(grid, mask, open, ideal, reach);
        const glm::vec2 at = grid.cellCenter(cell % grid.width(), cell / grid.width());
        layout.goals.push_back({"goal " + std::to_string(g + 1), Region::disc(at, request.goalRadius), request.onArrival});
    }
    return layout;
}

} // namespace tessera::crowd
