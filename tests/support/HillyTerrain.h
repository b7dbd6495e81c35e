#pragma once
/// @file HillyTerrain.h
/// A synthetic 2 km height map of regular hills and hollows, 8 m either side
/// of 100 m, 160 m from crest to crest, with a hollow at its centre (where
/// the crowd's layout puts the spawn): at low tessellation levels the drawn
/// ground lies metres away from the height field under every agent, the
/// case docs/CROWD.md (6.8) is about. Gentle enough (23 degrees at most) for
/// the crowd to walk all of it.

#include "SmallTerrain.h"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace tessera::test {

/// Writes the map into `outDir` once and returns its path; empty, with
/// `error` set, when it cannot. Written under a private name and renamed
/// into place, as smallTerrainCrop does, for tests running side by side.
inline std::string hillyTerrain(const std::filesystem::path& outDir, std::string& error) {
    constexpr uint32_t kSize = 513; // 4 m apart: 2048 m, 64 m patches
    constexpr double kSpacing = 4.0, kCentre = 1024.0, kWave = 160.0, kRelief = 8.0, kMetresPerUnit = 600.0 / 65535.0;
    const std::filesystem::path out = outDir / "hills_513.png";
    if (std::filesystem::exists(out)) return out.string();
    std::vector<uint16_t> samples;
    samples.reserve(size_t(kSize) * kSize);
    const double k = 2.0 * M_PI / kWave;
    for (uint32_t j = 0; j < kSize; ++j)
        for (uint32_t i = 0; i < kSize; ++i) {
            const double x = i * kSpacing - kCentre, z = j * kSpacing - kCentre;
            const double h = 100.0 - kRelief * std::cos(k * x) * std::cos(k * z);
            samples.push_back(uint16_t(std::lround(h / kMetresPerUnit)));
        }
    return writeHeightMapAtomically(out, kSize, samples, error);
}

} // namespace tessera::test
