#pragma once
/// @file MipChain.h
/// Box-filtered mip levels of RGBA8 images, made on the CPU for textures
/// that are drawn smaller than they are stored (a character's maps on a
/// creature a few dozen pixels tall, the terrain's detail textures far
/// away): each level averages 2x2 texels of the one above.

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::core {

/// How an image's red, green and blue bytes encode what is averaged
/// (alpha is always averaged as it is).
enum class MipEncoding {
    Linear, ///< the bytes themselves (normal maps, data)
    Srgb,   ///< sRGB-encoded colour, averaged in linear light (averaging the bytes would darken every level)
};

/// Levels of a `width` x `height` image down to 1 x 1, level 0 included.
uint32_t mipLevelCount(uint32_t width, uint32_t height);

/// The level below `level` (`width` x `height` RGBA8, rows tightly packed):
/// max(1, width / 2) x max(1, height / 2) texels, each the mean of the 2x2
/// block it covers (of its column or row alone where that side is 1; an odd
/// side's last column or row is left out, as a 2x box filter does).
std::vector<uint8_t> halveRgba8(std::span<const uint8_t> level, uint32_t width, uint32_t height, MipEncoding encoding);

} // namespace tessera::core
