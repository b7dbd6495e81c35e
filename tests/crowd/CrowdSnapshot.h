#pragma once
// Debugging aid for the crowd tests: a top-down picture of the agents (one
// pixel per `scale` metres), walls dark, agents coloured by goal group.

#include "tessera/core/ImageFile.h"
#include "tessera/crowd/Crowd.h"

#include <string>

namespace tessera::crowd::test {

inline void writeSnapshot(const Crowd& crowd, const std::string& path, float pixelsPerMetre = 4.0f,
                          glm::vec2 lo = glm::vec2(0.0f), glm::vec2 hi = glm::vec2(-1.0f)) {
    const NavGrid& grid = crowd.navGrid();
    if (hi.x < lo.x) hi = glm::vec2(float(grid.width()), float(grid.height())) * grid.cellSize();
    Rgba8Image image;
    image.width = uint32_t((hi.x - lo.x) * pixelsPerMetre);
    image.height = uint32_t((hi.y - lo.y) * pixelsPerMetre);
    image.pixels.assign(size_t(image.width) * image.height * 4, 255);
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const glm::vec2 p = lo + (glm::vec2(float(x), float(y)) + 0.5f) / pixelsPerMetre;
            if (!crowd.passable(p))
                for (int c = 0; c < 3; ++c) image.pixels[(size_t(y) * image.width + x) * 4 + c] = 60;
        }
    const uint8_t colours[4][3] = {{220, 40, 40}, {40, 90, 220}, {30, 160, 60}, {200, 150, 20}};
    const CrowdAgents& a = crowd.agents();
    for (size_t i = 0; i < a.size(); ++i) {
        const glm::vec2 c = (glm::vec2(a.position[i].x, a.position[i].z) - lo) * pixelsPerMetre;
        const float r = a.radius[i] * pixelsPerMetre;
        for (int y = int(c.y - r); y <= int(c.y + r); ++y)
            for (int x = int(c.x - r); x <= int(c.x + r); ++x) {
                if (x < 0 || y < 0 || x >= int(image.width) || y >= int(image.height)) continue;
                if (glm::distance(glm::vec2(float(x) + 0.5f, float(y) + 0.5f), c) > r) continue;
                uint8_t* px = &image.pixels[(size_t(y) * image.width + size_t(x)) * 4];
                for (int k = 0; k < 3; ++k) px[k] = uint8_t(px[k] == 255 ? colours[a.goalGroup[i] % 4][k] : 0);
            }
    }
    (void)writePng(path, image);
}

} // namespace tessera::crowd::test
