#pragma once
/// @file ImageCompare.h
/// Golden-image comparison with a stated tolerance and a diff image, over
/// the core's one image diff (tessera/core/ImageDiff.h).

#include "tessera/core/ImageDiff.h"
#include "tessera/core/ImageFile.h"

#include <string>

namespace tessera::test {

struct ImageTolerance {
    /// A pixel differs when any channel differs by more than this (0..255).
    int channelThreshold = kDiffChannelThreshold;
    /// At most this fraction of pixels may differ.
    double maxDifferingFraction = 0.005;
    /// The mean absolute channel difference over the image may not exceed this.
    double maxMeanDifference = 1.5;
};

struct ImageComparison {
    bool match = false;
    double differingFraction = 0.0;
    double meanDifference = 0.0;
    std::string message; ///< why it failed, with the figures
};

/// Compares `actual` with `expected`; on mismatch writes a diff image (changed
/// pixels red over a dimmed copy of the expected image) to `diffPath`.
ImageComparison compareImages(const Rgba8Image& actual, const Rgba8Image& expected, const ImageTolerance& tolerance,
                              const std::string& diffPath);

} // namespace tessera::test
