#pragma once
/// @file ImageDiff.h
/// A screenshot against the reference backend's, and the bytes the report
/// embeds (base64 data: URIs, so the HTML opens offline and alone).

#include "tessera/core/ImageFile.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::report {

/// A pixel differs when a channel differs by more than this (as the render
/// tests' golden comparison).
inline constexpr int kDiffChannelThreshold = 24;

struct ImageDiff {
    Rgba8Image image;               ///< differing pixels red over a dimmed reference
    double differingFraction = 0.0; ///< share of pixels that differ
    double meanDifference = 0.0;    ///< mean absolute channel difference (0..255)
};

/// Compares `image` with `reference`; fails when their sizes differ.
Result<ImageDiff> diffImages(const Rgba8Image& image, const Rgba8Image& reference);

/// Standard base64 (RFC 4648, with padding).
std::string base64(const std::vector<uint8_t>& bytes);

/// `data:image/png;base64,...` of `image`, encoded by the core's PNG encoder.
Result<std::string> pngDataUri(const Rgba8Image& image);

} // namespace tessera::report
