#include "ImpostorLayerImage.h"

#include <algorithm>
#include <cmath>

namespace tessera::character {
namespace {

constexpr uint32_t kCell = TS_IMPOSTOR_CELL;

glm::vec3 normalised(const glm::vec3& v, const glm::vec3& fallback) {
    const float l = glm::length(v);
    return l > 1e-12f ? v / l : fallback;
}

uint8_t toByte(float value) {
    return uint8_t(std::clamp(std::floor(value + 0.5f), 0.0f, 255.0f));
}

// One mip level below `above` (side `size`): a 2 x 2 box, colour and normal
// weighted by coverage so a silhouette's texels keep the creature's colour
// rather than the dilated surroundings'; where none of the four is covered,
// the plain mean (the dilated values, so lower mips never fade to black).
std::vector<ImpostorTexel> halve(const std::vector<ImpostorTexel>& above, uint32_t size) {
    const uint32_t half = size / 2;
    std::vector<ImpostorTexel> below(size_t(half) * half);
    for (uint32_t y = 0; y < half; ++y) {
        for (uint32_t x = 0; x < half; ++x) {
            const ImpostorTexel* t[4] = {&above[size_t(2 * y) * size + 2 * x], &above[size_t(2 * y) * size + 2 * x + 1],
                                         &above[size_t(2 * y + 1) * size + 2 * x],
                                         &above[size_t(2 * y + 1) * size + 2 * x + 1]};
            float weight = 0.0f;
            glm::vec3 colour(0.0f), normal(0.0f), plainColour(0.0f), plainNormal(0.0f);
            for (const ImpostorTexel* texel : t) {
                weight += texel->coverage;
                colour += texel->colour * texel->coverage;
                normal += texel->normal * texel->coverage;
                plainColour += texel->colour;
                plainNormal += texel->normal;
            }
            ImpostorTexel& out = below[size_t(y) * half + x];
            out.coverage = weight * 0.25f;
            out.colour = weight > 0.0f ? colour / weight : plainColour * 0.25f;
            out.normal = normalised(weight > 0.0f ? normal : plainNormal, glm::vec3(0.0f, 1.0f, 0.0f));
        }
    }
    return below;
}

void storeLevel(const std::vector<ImpostorTexel>& texels, std::vector<uint8_t>& albedo, std::vector<uint8_t>& normal,
                size_t offset) {
    for (size_t i = 0; i < texels.size(); ++i) {
        const ImpostorTexel& t = texels[i];
        uint8_t* a = albedo.data() + offset + 4 * i;
        uint8_t* n = normal.data() + offset + 4 * i;
        for (int c = 0; c < 3; ++c) {
            a[c] = toByte(t.colour[c]);
            n[c] = toByte((t.normal[c] * 0.5f + 0.5f) * 255.0f);
        }
        a[3] = toByte(t.coverage * 255.0f);
        n[3] = 255;
    }
}

} // namespace

void ImpostorLayerImage::dilateCell(glm::uvec2 cell, const glm::vec3& emptyColour, const glm::vec3& emptyNormal) {
    const uint32_t x0 = cell.x * kCell, y0 = cell.y * kCell;
    std::vector<uint8_t> filled(kCell * kCell);
    for (uint32_t y = 0; y < kCell; ++y)
        for (uint32_t x = 0; x < kCell; ++x) filled[y * kCell + x] = at(x0 + x, y0 + y).coverage > 0.0f;

    struct Fill {
        uint32_t x, y;
        glm::vec3 colour, normal;
    };
    std::vector<Fill> fills;
    for (uint32_t pass = 0; pass < kDilationTexels; ++pass) {
        // Read from the previous pass's state only, written after the scan:
        // the result does not depend on the scan order.
        fills.clear();
        for (uint32_t y = 0; y < kCell; ++y) {
            for (uint32_t x = 0; x < kCell; ++x) {
                if (filled[y * kCell + x]) continue;
                glm::vec3 colour(0.0f), normal(0.0f);
                uint32_t count = 0;
                for (uint32_t ny = y > 0 ? y - 1 : 0; ny <= std::min(y + 1, kCell - 1); ++ny) {
                    for (uint32_t nx = x > 0 ? x - 1 : 0; nx <= std::min(x + 1, kCell - 1); ++nx) {
                        if (!filled[ny * kCell + nx]) continue;
                        colour += at(x0 + nx, y0 + ny).colour;
                        normal += at(x0 + nx, y0 + ny).normal;
                        ++count;
                    }
                }
                if (count) fills.push_back({x, y, colour / float(count), normalised(normal, emptyNormal)});
            }
        }
        for (const Fill& f : fills) {
            at(x0 + f.x, y0 + f.y).colour = f.colour;
            at(x0 + f.x, y0 + f.y).normal = f.normal;
            filled[f.y * kCell + f.x] = 1;
        }
    }

    float weight = 0.0f;
    glm::vec3 colour(0.0f), normal(0.0f);
    for (uint32_t y = 0; y < kCell; ++y) {
        for (uint32_t x = 0; x < kCell; ++x) {
            const ImpostorTexel& t = at(x0 + x, y0 + y);
            weight += t.coverage;
            colour += t.colour * t.coverage;
            normal += t.normal * t.coverage;
        }
    }
    const glm::vec3 meanColour = weight > 0.0f ? colour / weight : emptyColour;
    const glm::vec3 meanNormal = weight > 0.0f ? normalised(normal, emptyNormal) : emptyNormal;
    for (uint32_t y = 0; y < kCell; ++y) {
        for (uint32_t x = 0; x < kCell; ++x) {
            if (filled[y * kCell + x]) continue;
            at(x0 + x, y0 + y).colour = meanColour;
            at(x0 + x, y0 + y).normal = meanNormal;
        }
    }
}

void ImpostorLayerImage::store(ImpostorAtlas& atlas, uint32_t layer) const {
    std::vector<ImpostorTexel> level = mTexels;
    uint32_t size = kSize;
    for (uint32_t m = 0; m < TS_IMPOSTOR_MIPS; ++m) {
        if (m > 0) {
            level = halve(level, size);
            size /= 2;
        }
        storeLevel(level, atlas.albedo[m], atlas.normal[m], size_t(atlas.layerBytes(m)) * layer);
    }
}

} // namespace tessera::character
