#pragma once
/// @file CharacterBenchFigures.h
/// The CPU-side figures of `--bench characters`: tessellated triangle counts,
/// the level matching the paper's amplification, Table 1's bytes and the
/// compressed vertex's error for each asset of the crowd.

#include "tessera/runtime/CharacterAssets.h"
#include "bench/CharacterBenchReport.h"

#include <cstdint>
#include <filesystem>
#include <optional>

namespace tessera::runtime {

/// Triangles one cage triangle becomes at `level` (triangle domain,
/// fractional-odd spacing, as every backend draws characters), for levels up
/// to 64.
uint64_t trianglesPerCageTriangle(float level);

/// The level in [1, maxLevel] (on a 0.01 grid) whose triangles per cage
/// triangle are closest, in ratio, to the paper's 1.6M / 5.2K; among levels
/// with the same count the highest, so it reads as an odd integer.
float paperAmplificationLevel(float maxLevel);

/// The creature generator's report beside `assetFile` (same name, .json), if
/// there is one with the sculpt's figures.
std::optional<SculptReport> readSculptReport(const std::filesystem::path& assetFile);

/// Table 1, amplification and compression error of one asset. `tableLevel`
/// sizes the dense mesh; `sharedLevel` and `paperLevel` the triangle counts.
CharacterAssetFigures assetFigures(const CrowdAsset& asset, float sharedLevel, float paperLevel, float tableLevel);

} // namespace tessera::runtime
