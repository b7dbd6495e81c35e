#pragma once
/// @file DataUri.h
/// The bytes the report embeds as base64 data: URIs (screenshots and their
/// diffs, made by the core's one image diff, tessera/core/ImageDiff.h), so
/// the HTML opens offline and alone.

#include "tessera/core/ImageFile.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::report {

/// Standard base64 (RFC 4648, with padding).
std::string base64(const std::vector<uint8_t>& bytes);

/// `data:image/png;base64,...` of `image`, encoded by the core's PNG encoder.
Result<std::string> pngDataUri(const Rgba8Image& image);

} // namespace tessera::report
