#pragma once
/// @file PngWriter16.h
/// Internal: the libpng writer behind saveHeightMapPng16 (kept apart so that
/// libpng's setjmp error handling stays in one small, C-like file).

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>

namespace tessera::terrain {

/// Writes a width x height 16-bit grayscale PNG from row-major samples.
/// Deterministic bytes: no tIME/text chunks, zlib level 6, Paeth filter on
/// every row. Removes the partial file and names it in the Error on failure.
Status writePngGray16(const std::filesystem::path& path, uint32_t width, uint32_t height,
                      const uint16_t* samples);

} // namespace tessera::terrain
