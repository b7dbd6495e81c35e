#pragma once
/// @file SyntheticImpostorAtlas.h
/// Test support: an impostor atlas (character::ImpostorAtlas, layout in
/// shaders/CrowdImpostor.h) made without the baker, so the GPU side can be
/// built and looked at on its own: in every cell of every layer an upright
/// ellipsoid (a creature-sized blob, 0.3 x 0.8 of the square), lit normals
/// facing the cell's view, coloured per (creature, clip, phase)
/// (syntheticImpostorColor), with TS_IMPOSTOR_MIPS box-filtered levels.

#include "tessera/character/ImpostorAtlas.h"
#include "tessera/shaders/CrowdImpostor.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tessera::test {

/// The base colour (sRGB bytes) of creature `creature`'s clip `clip`, phase `phase`.
inline glm::u8vec3 syntheticImpostorColor(uint32_t creature, uint32_t clip, uint32_t phase) {
    return {uint8_t(60 + 24 * (phase % TS_IMPOSTOR_PHASES)), uint8_t(60 + 45 * (clip % 4)),
            uint8_t(70 + 80 * (creature % 3))};
}

/// An atlas of `clips` clips (TS_IMPOSTOR_PHASES layers each) for creature
/// `creature`, framing the sphere (0, centreY, 0), `radius`. Also what tests
/// of the file format and the crowd checks use where any valid atlas will do.
inline character::ImpostorAtlas syntheticImpostorAtlas(uint32_t creature, uint32_t clips, float centreY = 0.75f,
                                                       float radius = 1.25f) {
    character::ImpostorAtlas atlas;
    atlas.size = TS_IMPOSTOR_VIEWS * TS_IMPOSTOR_CELL;
    atlas.layers = clips * TS_IMPOSTOR_PHASES;
    atlas.centreY = centreY;
    atlas.radius = radius;
    const uint32_t side = atlas.size;
    std::vector<uint8_t> albedo(size_t(side) * side * 4 * atlas.layers), normal(albedo.size());
    for (uint32_t layer = 0; layer < atlas.layers; ++layer) {
        const glm::u8vec3 color = syntheticImpostorColor(creature, layer / TS_IMPOSTOR_PHASES, layer % TS_IMPOSTOR_PHASES);
        for (uint32_t y = 0; y < side; ++y)
            for (uint32_t x = 0; x < side; ++x) {
                const glm::uvec2 cell(x / TS_IMPOSTOR_CELL, y / TS_IMPOSTOR_CELL);
                // (s, t) of the texel's centre within the cell's square.
                const glm::vec2 texel = glm::vec2(x % TS_IMPOSTOR_CELL, y % TS_IMPOSTOR_CELL) + 0.5f;
                const glm::vec2 st = (texel - float(TS_IMPOSTOR_BORDER)) /
                                     float(TS_IMPOSTOR_CELL - 2 * TS_IMPOSTOR_BORDER);
                const glm::vec2 e((2.0f * st.x - 1.0f) / 0.3f, (1.0f - 2.0f * st.y) / 0.8f);
                const float r2 = glm::dot(e, e);
                glm::vec3 right, up;
                const glm::vec3 d = shader::tsImpostorCellDirection(cell);
                shader::tsImpostorAxes(d, right, up);
                const glm::vec3 n =
                    r2 < 1.0f ? glm::normalize(e.x * right + e.y * up + std::sqrt(1.0f - r2) * d) : d;
                uint8_t* a = &albedo[((size_t(layer) * side + y) * side + x) * 4];
                uint8_t* m = &normal[((size_t(layer) * side + y) * side + x) * 4];
                a[0] = color.r, a[1] = color.g, a[2] = color.b, a[3] = r2 < 1.0f ? 255 : 0;
                for (int k = 0; k < 3; ++k) m[k] = uint8_t(std::lround((n[k] * 0.5f + 0.5f) * 255.0f));
                m[3] = 255;
            }
    }
    // Each mip a 2 x 2 box of the one above.
    auto halve = [](const std::vector<uint8_t>& level, uint32_t from, uint32_t layers) {
        const uint32_t to = from / 2;
        std::vector<uint8_t> out(size_t(to) * to * 4 * layers);
        for (uint32_t l = 0; l < layers; ++l)
            for (uint32_t y = 0; y < to; ++y)
                for (uint32_t x = 0; x < to; ++x)
                    for (int k = 0; k < 4; ++k) {
                        uint32_t sum = 0;
                        for (uint32_t dy = 0; dy < 2; ++dy)
                            for (uint32_t dx = 0; dx < 2; ++dx)
                                sum += level[((size_t(l) * from + 2 * y + dy) * from + 2 * x + dx) * 4 + k];
                        out[((size_t(l) * to + y) * to + x) * 4 + k] = uint8_t((sum + 2) / 4);
                    }
        return out;
    };
    atlas.albedo.push_back(std::move(albedo));
    atlas.normal.push_back(std::move(normal));
    for (uint32_t m = 1; m < TS_IMPOSTOR_MIPS; ++m) {
        atlas.albedo.push_back(halve(atlas.albedo.back(), side >> (m - 1), atlas.layers));
        atlas.normal.push_back(halve(atlas.normal.back(), side >> (m - 1), atlas.layers));
    }
    return atlas;
}

} // namespace tessera::test
