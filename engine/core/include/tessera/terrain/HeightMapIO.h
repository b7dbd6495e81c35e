#pragma once
/// @file HeightMapIO.h
/// Reading and writing height maps as grayscale PNG files.
///
/// Image row r is terrain row j = r (world z = r * spacing) and column c is
/// i = c (world x), so a top-down view of the terrain with +X to the right has
/// +Z pointing down the image. Every failure is a checked Error whose message
/// starts with the file's path ("terrain/height.png: not a PNG file").

#include "tessera/core/Result.h"
#include "tessera/terrain/HeightField.h"
#include "tessera/terrain/TerrainScale.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace tessera::terrain {

/// Smallest accepted height map side, in samples (bilinear needs a 2x2 cell).
inline constexpr uint32_t kMinHeightMapSide = 2;
/// Largest accepted height map side, in samples.
inline constexpr uint32_t kMaxHeightMapSide = 16384;

/// Loads an 8- or 16-bit grayscale PNG (gray + alpha is accepted; the alpha
/// channel is ignored). 8-bit values v become v * 257, so 255 maps to 65535.
/// Fails, naming the file, when it is missing, not a PNG, corrupt (with
/// stb_image's reason), in colour ("expected a grayscale PNG, got 3 channels";
/// palette images count as colour), or smaller than 2x2 or larger than
/// 16384 on a side.
Result<HeightField> loadHeightMapPng(const std::filesystem::path& path, TerrainScale scale = {});

/// Writes `samples` (row-major, width * height) as a 16-bit grayscale PNG.
/// Encoded by the core's one PNG encoder (tessera/core/ImageFile.h), so the
/// bytes depend only on the arguments and equal inputs give byte-identical
/// files. The folder must exist; the file is overwritten; on failure it is
/// removed and the Error names it.
Status saveHeightMapPng16(const std::filesystem::path& path, uint32_t width, uint32_t height,
                          const std::vector<uint16_t>& samples);

} // namespace tessera::terrain
