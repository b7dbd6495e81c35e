#pragma once
/// @file FeatureMask.h
/// Optional device features a host can hide from the backends, to see what
/// a device without them does (the demo's --hide-features): each backend
/// then either refuses, naming what it lacks, or the selection falls back to
/// the next backend. A hidden feature is also not enabled on the device, so
/// the validation layer catches a backend that uses it anyway.

#include "tessera/device/DeviceFeatures.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tessera::device {

/// A set of DeviceFeatures flags, one bit per name of featureMaskNames().
struct FeatureMask {
    uint32_t bits = 0;
    bool empty() const { return bits == 0; }
};

/// The feature called `name` ("tessellation", "multi-draw-indirect": the
/// words of featureMaskNames()) as a mask of one bit; nullopt for any other
/// word. Hosts read their lists of names themselves (the command line's
/// reader is tessera/cli/FeatureMaskText.h).
std::optional<FeatureMask> featureNamed(std::string_view name);

/// The names featureNamed knows, comma separated.
std::string featureMaskNames();

/// Clears the features of `mask` in `features` (and the tessellation level
/// with tessellation).
void applyFeatureMask(const FeatureMask& mask, DeviceFeatures& features);

} // namespace tessera::device
