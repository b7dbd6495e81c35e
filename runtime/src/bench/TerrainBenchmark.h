#pragma once
/// @file TerrainBenchmark.h
/// `tessera-demo --bench terrain` (`./tessera bench terrain`): the first
/// paper's Table 2 on every device and every backend that draws the modes.

#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"

namespace tessera::runtime {

/// For each device (--device, else every Vulkan device: lavapipe and any GPU)
/// and backend (--backend, else all GPU backends), renders a far and a
/// close-up view in each terrain mode the backend draws, --warmup frames
/// (default 3) then --frames frames (default 10), at --width x --height
/// (1280x720 unless given). Writes the JSON to --out or stdout and the table
/// with the ratios to stdout (stderr when the JSON goes to stdout).
Status runTerrainBenchmark(const Options& options);

} // namespace tessera::runtime
