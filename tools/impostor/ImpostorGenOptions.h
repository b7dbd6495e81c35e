#pragma once
/// @file ImpostorGenOptions.h
/// Command-line options of tessera-impostorgen.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace tessera::impostorgen {

/// Parsed command line.
struct ImpostorGenOptions {
    std::filesystem::path in;  ///< --in: the character (.glb or .gltf; required unless --help).
    std::filesystem::path out; ///< --out; empty: `in` with the extension .impostor.
    uint32_t threads = 0;      ///< --threads; 0: all hardware threads (never changes the output).
    bool quiet = false;        ///< --quiet: no summary line.
    bool help = false;         ///< --help / -h: print usage and exit 0.
};

/// Parses argv[1..argc) with the shared parser (tessera::cli). Fails with a
/// one-line message naming the flag.
Result<ImpostorGenOptions> parseImpostorGenOptions(int argc, const char* const* argv);

/// The --help text (also printed after a command-line error).
std::string impostorGenUsage();

} // namespace tessera::impostorgen
