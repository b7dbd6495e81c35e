#pragma once
/// @file HeightGenOptions.h
/// Command-line options of tessera-heightgen.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace tessera::heightgen {

/// Parsed command line. Defaults match the build's content map.
struct HeightGenOptions {
    uint32_t size = 2048;                   ///< --size: power of two, 64..8192.
    uint64_t seed = 1;                      ///< --seed.
    std::filesystem::path out;              ///< --out (required unless --help).
    std::optional<uint32_t> erosionDroplets; ///< --erosion-droplets; unset: scaled with area.
    uint32_t threads = 0;                   ///< --threads; 0: all hardware threads.
    bool quiet = false;                     ///< --quiet: no progress, no summary.
    bool help = false;                      ///< --help / -h: print usage and exit 0.
};

/// Parses argv[1..argc) with the shared parser (tessera::cli): "--flag value"
/// or "--flag=value". Fails with a one-line message naming the flag.
Result<HeightGenOptions> parseHeightGenOptions(int argc, const char* const* argv);

/// The --help text (also printed after a command-line error).
std::string heightGenUsage();

} // namespace tessera::heightgen
