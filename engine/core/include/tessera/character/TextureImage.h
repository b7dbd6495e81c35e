#pragma once
/// @file TextureImage.h
/// A decoded 2D texture held on the CPU (base colour, normal or displacement map).

#include <cstdint>
#include <vector>

namespace tessera::character {

/// Pixel formats a character's textures use.
enum class TextureFormat : uint8_t {
    Rgba8,  ///< 4 bytes per texel; base colour (sRGB) or tangent-space normal map (linear)
    R16,    ///< one little-endian uint16 per texel; displacement maps
};

/// Texels row by row from the top (v = 0) row, tightly packed.
struct TextureImage {
    uint32_t width = 0;
    uint32_t height = 0;
    TextureFormat format = TextureFormat::Rgba8;
    std::vector<uint8_t> bytes;

    bool empty() const { return width == 0 || height == 0; }
    uint32_t bytesPerTexel() const { return format == TextureFormat::Rgba8 ? 4u : 2u; }
};

} // namespace tessera::character
