#pragma once
/// @file ContentLocator.h
/// Finds the generated content directory (height maps, models).

#include "tessera/core/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tessera::runtime {

/// The content roots, in the order they are searched: `contentDir` (the
/// host's choice, tessera-demo's --content), $TESSERA_CONTENT_DIR, then
/// relative to libtessera_runtime.so (found with dladdr, so wherever the
/// game's executable is): the build tree's `content/` and the install's
/// `share/tessera/content`, and last the install's absolute location.
std::vector<std::filesystem::path> contentRoots(const std::string& contentDir);

/// Resolves `relative` (e.g. "terrain/height.png") against contentRoots().
/// The error lists where it looked and how to build the content.
Result<std::filesystem::path> locateContent(const std::string& contentDir, const std::string& relative);

} // namespace tessera::runtime
