#pragma once
/// @file CrowdBenchmark.h
/// `tessera-demo --bench crowd-sim` (`./tessera bench crowd-sim`): the crowd
/// simulation's cost and behaviour per crowd size, on the CPU alone.

#include "tessera/runtime/Options.h"
#include "tessera/core/Result.h"

namespace tessera::runtime {

/// On the demo's terrain (the generated content, or --heightmap), for each
/// --agents size (default 1000, 10000 and 65000): a fresh copy of the
/// terrain, a planned layout (CrowdSetup: four goal groups, Wander), the
/// crowd created (timed), --warmup steps (default 60) then --steps measured
/// steps (default 300), while deterministic craters (--seed) land among the
/// agents every kMeteorIntervalSeconds of simulated time. --threads pins the
/// crowd's threads. Every size is checked against the machine's memory
/// before the first runs. Writes the JSON to --out or stdout and the table to
/// stdout (stderr when the JSON goes to stdout). Creates no Vulkan instance
/// or device, so it runs on machines without a driver.
Status runCrowdBenchmark(const Options& options);

/// Simulated seconds between two craters.
inline constexpr double kMeteorIntervalSeconds = 3.0;

} // namespace tessera::runtime
