#include "tessera/core/MipChain.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tessera::core {
namespace {

float toLinear(uint8_t v) {
    const float c = float(v) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

uint8_t toSrgb(float c) {
    c = std::clamp(c, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return uint8_t(std::lround(s * 255.0f));
}

const std::array<float, 256>& linearTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (uint32_t v = 0; v < 256; ++v) t[v] = toLinear(uint8_t(v));
        return t;
    }();
    return table;
}

} // namespace

uint32_t mipLevelCount(uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    for (uint32_t side = std::max(width, height); side > 1; side /= 2) ++levels;
    return levels;
}

std::vector<uint8_t> halveRgba8(std::span<const uint8_t> level, uint32_t width, uint32_t height, MipEncoding encoding) {
    const uint32_t w = std::max(1u, width / 2), h = std::max(1u, height / 2);
    // The block's second column or row: the first again where the side is 1.
    const uint32_t dx = width > 1 ? 1u : 0u, dy = height > 1 ? 1u : 0u;
    const std::array<float, 256>& linear = linearTable();
    std::vector<uint8_t> out(size_t(w) * h * 4);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t x0 = 2 * size_t(x) * dx, y0 = 2 * size_t(y) * dy;
            const size_t texels[4] = {y0 * width + x0, y0 * width + x0 + dx, (y0 + dy) * width + x0,
                                      (y0 + dy) * width + x0 + dx};
            for (uint32_t c = 0; c < 4; ++c) {
                uint8_t* dst = &out[(size_t(y) * w + x) * 4 + c];
                if (c == 3 || encoding == MipEncoding::Linear) {
                    uint32_t sum = 2;
                    for (size_t t : texels) sum += level[t * 4 + c];
                    *dst = uint8_t(sum / 4);
                    continue;
                }
                float sum = 0.0f;
                for (size_t t : texels) sum += linear[level[t * 4 + c]];
                *dst = toSrgb(0.25f * sum);
            }
        }
    return out;
}

} // namespace tessera::core
