#pragma once
/// @file TexGenOptions.h
/// Command-line options of tessera-texgen.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace tessera::texgen {

/// Parsed command line. Defaults match the build's content.
struct TexGenOptions {
    uint32_t size = 512;            ///< --size: texels per side, a power of two in 16..4096.
    uint64_t seed = 1;              ///< --seed.
    std::filesystem::path outDir;   ///< --out-dir (required unless --help).
    bool quiet = false;             ///< --quiet: no summary line.
    bool help = false;              ///< --help / -h: print usage and exit 0.
};

/// Parses argv[1..argc) with the shared parser (tessera::cli). Fails with a
/// one-line message naming the flag.
Result<TexGenOptions> parseTexGenOptions(int argc, const char* const* argv);

/// The --help text (also printed after a command-line error).
std::string texGenUsage();

} // namespace tessera::texgen
