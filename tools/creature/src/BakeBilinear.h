#pragma once
/// @file BakeBilinear.h
/// The texture fetch the renderers perform on baked maps, on the CPU: texel
/// centres at (i + 0.5) / size, bilinear filtering, clamp-to-edge, mip 0.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::creature {

/// The four texels (row-major indices, row 0 at v = 0) and weights a
/// bilinear fetch at `uv` blends.
struct BilinearTaps {
    std::array<uint32_t, 4> index{};
    std::array<float, 4> weight{};
};

inline BilinearTaps bilinearTaps(glm::vec2 uv, uint32_t size) {
    float x = uv.x * static_cast<float>(size) - 0.5f;
    float y = uv.y * static_cast<float>(size) - 0.5f;
    float fx0 = std::floor(x), fy0 = std::floor(y);
    float fx = x - fx0, fy = y - fy0;
    int last = static_cast<int>(size) - 1;
    int x0 = std::clamp(static_cast<int>(fx0), 0, last), x1 = std::clamp(static_cast<int>(fx0) + 1, 0, last);
    int y0 = std::clamp(static_cast<int>(fy0), 0, last), y1 = std::clamp(static_cast<int>(fy0) + 1, 0, last);
    BilinearTaps taps;
    taps.index = {static_cast<uint32_t>(y0) * size + static_cast<uint32_t>(x0),
                  static_cast<uint32_t>(y0) * size + static_cast<uint32_t>(x1),
                  static_cast<uint32_t>(y1) * size + static_cast<uint32_t>(x0),
                  static_cast<uint32_t>(y1) * size + static_cast<uint32_t>(x1)};
    taps.weight = {(1.0f - fx) * (1.0f - fy), fx * (1.0f - fy), (1.0f - fx) * fy, fx * fy};
    return taps;
}

/// Bilinear fetch of a float map of `size` x `size` texels.
inline float sampleBilinear(const std::vector<float>& map, uint32_t size, glm::vec2 uv) {
    BilinearTaps taps = bilinearTaps(uv, size);
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) sum += taps.weight[k] * map[taps.index[k]];
    return sum;
}

} // namespace tessera::creature
