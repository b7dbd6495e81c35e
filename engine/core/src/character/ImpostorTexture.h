#pragma once
// ImpostorTexture: a character's base colour map as the impostor baker
// samples it (private to the baker): box-filtered down to about one texel per
// impostor sample, so a 1024^2 map seen through a 30-texel cell does not
// alias into noise, then read bilinearly with clamp to edge, as the GPU
// samples the character's map.

#include "tessera/character/TextureImage.h"

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace tessera::character {

class ImpostorTexture {
public:
    /// A constant colour (0..255 per channel): a character without a map.
    explicit ImpostorTexture(const glm::vec3& colour);
    /// `image` (Rgba8, bytes matching its size) halved `levels` times
    /// (each level a 2 x 2 box; a side stops at 1 texel).
    ImpostorTexture(const TextureImage& image, uint32_t levels);

    /// The colour at `uv` (0..255 per channel, in the map's stored sRGB
    /// values: the GPU reads it UNORM and filters those).
    glm::vec3 sample(const glm::vec2& uv) const;

    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }

private:
    const glm::vec3& texel(int x, int y) const;

    uint32_t mWidth = 1;
    uint32_t mHeight = 1;
    std::vector<glm::vec3> mTexels; ///< row by row from the top (v = 0)
};

} // namespace tessera::character
