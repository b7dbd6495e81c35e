#pragma once
/// @file Runner.h
/// The crowd/terrain demo: loads content, runs the frame loop on the chosen
/// backend, and writes screenshots, captures and benchmarks.

#include "tessera/runtime/Options.h"

namespace tessera::runtime {

/// Runs the demo; returns the process exit code (0 on success).
int execute(const Options& options);

} // namespace tessera::runtime
