#pragma once
/// @file GlbImageEncoder.h
/// PNG encoding of character maps for embedding in .glb files: the texture
/// image's checks in front of the core's one encoder (tessera/core/ImageFile.h).

#include "tessera/character/TextureImage.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <vector>

namespace tessera::creature {

/// Encodes `image` as PNG bytes: Rgba8 as 8-bit RGBA, R16 as 16-bit
/// grayscale (the displacement map keeps its full precision). The bytes
/// depend on the texels only (the core encoder pins every setting). Fails
/// (naming `what`) on an empty image or a byte count that does not match the
/// size.
Result<std::vector<uint8_t>> encodePng(const character::TextureImage& image, const char* what);

} // namespace tessera::creature
