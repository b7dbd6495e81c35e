#include "ImpostorTexture.h"

#include <algorithm>
#include <cmath>

namespace tessera::character {

ImpostorTexture::ImpostorTexture(const glm::vec3& colour) : mTexels{colour} {}

ImpostorTexture::ImpostorTexture(const TextureImage& image, uint32_t levels)
    : mWidth(image.width), mHeight(image.height) {
    mTexels.resize(size_t(mWidth) * mHeight);
    for (size_t i = 0; i < mTexels.size(); ++i)
        mTexels[i] = glm::vec3(image.bytes[4 * i], image.bytes[4 * i + 1], image.bytes[4 * i + 2]);
    for (uint32_t level = 0; level < levels && (mWidth > 1 || mHeight > 1); ++level) {
        const uint32_t w = std::max(mWidth / 2, 1u), h = std::max(mHeight / 2, 1u);
        std::vector<glm::vec3> half(size_t(w) * h);
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) {
                const int sx = int(2 * x), sy = int(2 * y);
                half[size_t(y) * w + x] =
                    (texel(sx, sy) + texel(sx + 1, sy) + texel(sx, sy + 1) + texel(sx + 1, sy + 1)) * 0.25f;
            }
        }
        mTexels = std::move(half);
        mWidth = w;
        mHeight = h;
    }
}

const glm::vec3& ImpostorTexture::texel(int x, int y) const {
    const int cx = std::clamp(x, 0, int(mWidth) - 1), cy = std::clamp(y, 0, int(mHeight) - 1);
    return mTexels[size_t(cy) * mWidth + size_t(cx)];
}

glm::vec3 ImpostorTexture::sample(const glm::vec2& uv) const {
    // Clamped first: clamp to edge makes anything outside [0, 1] the edge
    // anyway, and a NaN becomes 0 rather than an undefined index.
    const float u = std::isnan(uv.x) ? 0.0f : std::clamp(uv.x, 0.0f, 1.0f);
    const float v = std::isnan(uv.y) ? 0.0f : std::clamp(uv.y, 0.0f, 1.0f);
    const float x = u * float(mWidth) - 0.5f, y = v * float(mHeight) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = int(fx), iy = int(fy);
    const float wx = x - fx, wy = y - fy;
    const glm::vec3 top = texel(ix, iy) * (1.0f - wx) + texel(ix + 1, iy) * wx;
    const glm::vec3 bottom = texel(ix, iy + 1) * (1.0f - wx) + texel(ix + 1, iy + 1) * wx;
    return top * (1.0f - wy) + bottom * wy;
}

} // namespace tessera::character
