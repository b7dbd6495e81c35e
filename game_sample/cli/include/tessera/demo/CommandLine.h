#pragma once
/// @file CommandLine.h
/// tessera-demo's command line into the runtime's Options, through the
/// shared parser (tessera::cli, CLI11): `--flag value` or `--flag=value`,
/// every flag documented in helpText(). Parsing never exits; it returns one
/// line naming the bad flag.

#include "tessera/core/Result.h"
#include "tessera/runtime/Options.h"

#include <string>
#include <vector>

namespace tessera::demo {

/// Parses argv (without argv[0]).
Result<runtime::Options> parseCommandLine(const std::vector<std::string>& args);

/// The --help text, generated from the declared flags (DemoFlags).
std::string helpText();

} // namespace tessera::demo
