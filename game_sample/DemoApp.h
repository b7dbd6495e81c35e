#pragma once
/// @file DemoApp.h
/// The crowd/terrain demo: loads content, runs the frame loop on the chosen
/// backend, and writes screenshots, captures and benchmarks.

#include "DemoOptions.h"

namespace tessera::demo {

/// Runs the demo; returns the process exit code (0 on success).
int runDemo(const DemoOptions& options);

} // namespace tessera::demo
