#pragma once
/// @file FeatureMask.h
/// Optional device features a host can hide from the backends, to see what
/// a device without them does (the demo's --hide-features): each backend
/// then either refuses, naming what it lacks, or the selection falls back to
/// the next backend. A hidden feature is also not enabled on the device, so
/// the validation layer catches a backend that uses it anyway.

#include "tessera/device/DeviceFeatures.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace tessera::device {

/// A set of DeviceFeatures flags, one bit per name of featureMaskNames().
struct FeatureMask {
    uint32_t bits = 0;
    bool empty() const { return bits == 0; }
};

/// Parses a comma list of feature names ("tessellation,geometry"); an error
/// naming the unknown one and the known names otherwise.
Result<FeatureMask> parseFeatureMask(std::string_view list);

/// The names parseFeatureMask accepts, comma separated.
std::string featureMaskNames();

/// Clears the features of `mask` in `features` (and the tessellation level
/// with tessellation).
void applyFeatureMask(const FeatureMask& mask, DeviceFeatures& features);

} // namespace tessera::device
