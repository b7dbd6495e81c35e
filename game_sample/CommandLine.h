#pragma once
/// @file CommandLine.h
/// tessera-demo's command line into the runtime's Options. Every flag is
/// documented in helpText(); parsing never exits, it returns an error naming
/// the bad flag.

#include "tessera/core/Result.h"
#include "tessera/runtime/Options.h"

#include <string>
#include <vector>

namespace tessera::demo {

/// Parses argv (without argv[0]).
Result<runtime::Options> parseCommandLine(const std::vector<std::string>& args);

/// The --help text.
const char* helpText();

} // namespace tessera::demo
