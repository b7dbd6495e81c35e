#pragma once
/// @file BenchTrace.h
/// What the benchmarks (--bench terrain, --bench characters) share about
/// their per-backend Chrome traces: where they go, the names of their row
/// slices, and writing one with the session's device in its metadata.

#include "DemoOptions.h"
#include "RenderSession.h"
#include "tessera/core/Result.h"
#include "tessera/profiler/Profiler.h"

#include <filesystem>
#include <string>

namespace tessera::demo {

/// Where the per-backend traces go ("" for none): --out-dir, else with
/// --backend all next to --out or in the current directory.
std::filesystem::path benchTraceDirectory(const DemoOptions& options);

/// A CPU-track slice name that lives as long as the process (CpuEvent keeps
/// only the pointer, and the global profiler is never destroyed).
const char* internBenchName(const std::string& name);

/// Writes `profiler`'s events to `path` as a Chrome trace whose metadata
/// names `application` and the session's backend, device, driver and size.
Status writeBenchTrace(const profiler::Profiler& profiler, const std::string& path, const std::string& application,
                       const RenderSession& session);

} // namespace tessera::demo
