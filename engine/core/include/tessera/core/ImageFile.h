#pragma once
/// @file ImageFile.h
/// PNG images: the one encoder and the one decoder of the code base
/// (screenshots, golden images and diffs, height maps, the maps embedded in
/// `.glb` characters and the glTF loader's textures).
///
/// Encoding is libpng's (stb_image_write cannot write 16-bit samples, which
/// height maps and displacement maps need). Every setting libpng would choose
/// by default or by the clock is pinned (zlib level 6, the adaptive filter
/// heuristic, no time or text chunks), so the bytes depend only on the pixels
/// and the zlib build: generated content is byte-identical run to run.
/// Decoding is stb_image's, from memory (readImageHeader, decodeImage) or from
/// a file (readPng); it also reads the JPEG textures glTF allows.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace tessera {

struct Rgba8Image {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> pixels; ///< width * height * 4 bytes, rows top to bottom
};

/// The sample layouts the encoder writes.
enum class PngLayout {
    Rgba8,  ///< 4 bytes a pixel: red, green, blue, alpha
    Gray8,  ///< 1 byte a pixel
    Gray16, ///< one uint16_t a pixel, in the host's byte order (PNG's big-endian is the encoder's job)
};

/// Pixels to encode, borrowed: `width * height` pixels of `layout`, tightly
/// packed, rows top to bottom.
struct PngPixels {
    uint32_t width = 0;
    uint32_t height = 0;
    PngLayout layout = PngLayout::Rgba8;
    const void* data = nullptr;
};

/// Bytes per pixel of `layout` (4, 1 or 2).
uint32_t bytesPerPixel(PngLayout layout);

/// Encodes `pixels` as a PNG file's bytes, in memory. Fails on an empty image,
/// null data or a side above 2^31 - 1; the message does not name a file.
Result<std::vector<uint8_t>> encodePng(const PngPixels& pixels);

/// Encodes `pixels` and writes them to `path`, overwriting it. The folder must
/// exist. On failure the partial file is removed and the Error names it.
Status writePng(const std::filesystem::path& path, const PngPixels& pixels);

/// Writes an RGBA8 PNG, creating the parent folders first (screenshots and
/// diffs name folders freely); the error names the file.
Status writePng(const std::filesystem::path& path, const Rgba8Image& image);

/// What an image's header says, read without decoding its pixels.
struct ImageHeader {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t channels = 0;   ///< as stored: 1 gray, 2 gray and alpha, 3 RGB, 4 RGBA
    bool sixteenBit = false; ///< 16 bits a sample (a PNG's)
};

/// Pixels decoded into one of the encoder's layouts.
struct DecodedImage {
    uint32_t width = 0;
    uint32_t height = 0;
    PngLayout layout = PngLayout::Rgba8;
    /// `width * height` pixels of `layout`, tightly packed, rows top to
    /// bottom; Gray16 samples in the host's byte order.
    std::vector<uint8_t> bytes;
};

/// Reads the header of an image file's bytes (PNG, or JPEG). The Error holds
/// the decoder's reason alone ("bad png sig"): the caller names the file.
Result<ImageHeader> readImageHeader(std::span<const uint8_t> bytes);

/// Decodes an image file's bytes (PNG, or JPEG) into `layout`: a gray layout
/// drops alpha and takes colour as luma; Gray16 widens 8-bit samples by 257
/// (0xAB to 0xABAB) and the 8-bit layouts keep a 16-bit sample's high byte.
/// The Error holds the decoder's reason alone, as readImageHeader's.
Result<DecodedImage> decodeImage(std::span<const uint8_t> bytes, PngLayout layout);

/// Reads any PNG as RGBA8; the error names the file and the problem.
Result<Rgba8Image> readPng(const std::filesystem::path& path);

} // namespace tessera
