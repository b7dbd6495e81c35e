#pragma once
/// @file FeatureMaskText.h
/// Device features to hide, as a command line writes them: a comma list of
/// the core's feature names ("tessellation,geometry"; the demo's
/// --hide-features), read by the one list reader's rules (NumberList.h).

#include "tessera/core/Result.h"
#include "tessera/device/FeatureMask.h"

#include <string_view>

namespace tessera::cli {

/// Parses a comma list of feature names (device::featureNamed); "" hides
/// nothing. Every item must be a name ("a,,b" and "a," are typos): an Error
/// `unknown feature "x" (known: tessellation, geometry, ...)` otherwise.
Result<device::FeatureMask> parseFeatureMask(std::string_view list);

} // namespace tessera::cli
