#pragma once
/// @file CreatureGenOptions.h
/// Command-line options of tessera-creaturegen.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <string>

namespace tessera::creature {

/// Parsed command line.
struct CreatureGenOptions {
    uint32_t seed = 1;                      ///< --seed
    std::filesystem::path out;              ///< --out FILE.glb (required unless --help)
    std::filesystem::path report;           ///< --report FILE.json (optional)
    uint32_t mapSize = 2048;                ///< --map-size: displacement/normal map size, 64..2048
    uint32_t sculptTriangles = 1'000'000;   ///< --sculpt-triangles: 10K..20M
    uint32_t cageTriangles = 5'000;         ///< --cage-triangles: 500..50K
    bool uncompressed = false;              ///< --uncompressed: no Draco
    bool quiet = false;                     ///< --quiet: no progress bar or summary
    bool help = false;                      ///< --help / -h
};

/// Parses argv[1..argc) with the shared parser (tessera::cli): "--flag value"
/// or "--flag=value"; fails with one line naming the flag at fault.
Result<CreatureGenOptions> parseCreatureGenOptions(int argc, const char* const* argv);

/// Usage text for --help and after a command-line error.
std::string creatureGenUsage();

} // namespace tessera::creature
