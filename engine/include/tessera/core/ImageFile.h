#pragma once
/// @file ImageFile.h
/// RGBA8 images on disk (PNG), for screenshots, golden images and diffs.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace tessera {

struct Rgba8Image {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> pixels; ///< width * height * 4 bytes, rows top to bottom
};

/// Writes an RGBA8 PNG; the error names the file.
Status writePng(const std::filesystem::path& path, const Rgba8Image& image);
/// Reads any PNG as RGBA8; the error names the file and the problem.
Result<Rgba8Image> readPng(const std::filesystem::path& path);

} // namespace tessera
