#pragma once
/// @file MipImage.h
/// RGBA8 images uploaded with their whole mip chain (core::halveRgba8): the
/// characters' maps and the terrain's detail textures.

#include "tessera/core/MipChain.h"
#include "tessera/gpu/Image.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tessera::backends {

/// An image of `layers.size()` layers of `width` x `height` RGBA8 texels
/// (each layer's level 0, rows tightly packed) in `format`, every mip down
/// to 1 x 1 made under `encoding`, left shader-readable. `smallest`, when
/// given, receives each layer's 1 x 1 level (its average).
gpu::Image makeMippedRgba8(gpu::Device& device, std::span<const std::span<const uint8_t>> layers, uint32_t width,
                           uint32_t height, VkFormat format, core::MipEncoding encoding, const std::string& name,
                           std::vector<std::array<uint8_t, 4>>* smallest = nullptr);

} // namespace tessera::backends
