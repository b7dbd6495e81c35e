#include "TileAtlas.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace tessera::subdiv::detail {

Result<TileAtlas> TileAtlas::pack(std::span<const glm::uvec2> footprints, uint32_t maxSide) {
    TileAtlas atlas;
    atlas.origins.resize(footprints.size());
    uint64_t area = 0;
    uint32_t widest = 1;
    for (const glm::uvec2& f : footprints) {
        area += uint64_t(f.x) * f.y;
        widest = std::max(widest, f.x);
    }
    uint32_t width = 1;
    while (uint64_t(width) * width < area) width *= 2;
    width = std::max(width, widest);
    // Tallest first, then widest, then in tile order: a stable layout for a
    // given set of sizes.
    std::vector<uint32_t> order(footprints.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        if (footprints[a].y != footprints[b].y) return footprints[a].y > footprints[b].y;
        if (footprints[a].x != footprints[b].x) return footprints[a].x > footprints[b].x;
        return a < b;
    });
    uint32_t x = 0, shelfY = 0, shelfHeight = 0;
    for (uint32_t tile : order) {
        const glm::uvec2 f = footprints[tile];
        if (x + f.x > width) {
            shelfY += shelfHeight;
            x = 0;
            shelfHeight = 0;
        }
        atlas.origins[tile] = {x, shelfY};
        x += f.x;
        shelfHeight = std::max(shelfHeight, f.y);
    }
    atlas.width = width;
    atlas.height = std::max(shelfY + shelfHeight, 1u);
    if (atlas.width > maxSide || atlas.height > maxSide)
        return fail("displacement tiles: the texture would be ", std::to_string(atlas.width), " x ",
                    std::to_string(atlas.height), " texels, more than ", std::to_string(maxSide), " a side");
    return atlas;
}

} // namespace tessera::subdiv::detail
