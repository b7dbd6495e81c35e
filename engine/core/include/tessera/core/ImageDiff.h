#pragma once
/// @file ImageDiff.h
/// The one comparison of two RGBA8 images: the render tests' golden and
/// parity checks (tests/support/ImageCompare) and the comparison report's
/// screenshot diffs (tools/report) read the same figures and draw the same
/// diff image.

#include "tessera/core/ImageFile.h"
#include "tessera/core/Result.h"

namespace tessera {

/// A pixel differs when one of its colour channels differs by more than this
/// (0..255), unless a caller says otherwise: the golden images' tolerance and
/// the report's.
inline constexpr int kDiffChannelThreshold = 24;

/// Where and how much two images differ.
struct ImageDiff {
    Rgba8Image image;               ///< differing pixels red over the reference dimmed to a quarter
    double differingFraction = 0.0; ///< share of pixels that differ
    double meanDifference = 0.0;    ///< mean absolute difference of the colour channels (0..255)
};

/// Compares `image` with `reference`, channel by channel (red, green, blue;
/// alpha is not compared): a pixel differs when a channel differs by more
/// than `channelThreshold`. Fails when their sizes differ or a pixel array is
/// shorter than its size says.
Result<ImageDiff> diffImages(const Rgba8Image& image, const Rgba8Image& reference,
                             int channelThreshold = kDiffChannelThreshold);

} // namespace tessera
