#pragma once
/// @file ContentLocator.h
/// Finds the generated content directory (height maps, models).

#include "tessera/core/Result.h"

#include <filesystem>
#include <string>

namespace tessera::demo {

/// Resolves `relative` (e.g. "terrain/height.png") against, in order: the
/// --content directory, $TESSERA_CONTENT_DIR, <exe>/../content (build tree)
/// and <exe>/../share/tessera/content (install tree). The error lists where
/// it looked and how to build the content.
Result<std::filesystem::path> locateContent(const std::string& contentDir, const std::string& relative);

} // namespace tessera::demo
