#pragma once
/// @file DemoRun.h
/// --run: tessera-demo's terrain benchmark on every backend and one
/// screenshot per backend, into the report's folder.

#include "ReportOptions.h"

#include "tessera/core/Result.h"

namespace tessera::reporttool {

/// tessera-demo next to this executable (/proc/self/exe), or `options.demo`.
Result<std::filesystem::path> findDemo(const ReportOptions& options);

/// Runs the benchmark (`--bench terrain --backend all --out DIR/bench.json
/// --out-dir DIR`), then for each backend it recorded a screenshot of the
/// terrain scene from `options.camera` (`DIR/screenshot-<backend>.png`). The
/// demo's output passes through; a failed run names its command line.
Status runDemo(const ReportOptions& options, const std::filesystem::path& demo);

} // namespace tessera::reporttool
