#pragma once
/// @file BenchOutputs.h
/// What the benchmarks (--bench terrain, --bench characters) share about
/// their outputs: the JSON and the table (--out, or stdout and stderr), and
/// the per-backend Chrome traces (where they go, the names of their row
/// slices, the session's device in their metadata).

#include "tessera/runtime/Options.h"
#include "tessera/runtime/RenderSession.h"
#include "tessera/core/Result.h"
#include "tessera/profiler/Profiler.h"

#include <filesystem>
#include <string>

namespace tessera::runtime {

/// Writes the benchmark's `json` to --out and its `table` to stdout, or,
/// without --out, the JSON to stdout and the table to stderr (so stdout
/// stays clean JSON). An --out that cannot be written is an error naming it.
Status writeBenchOutputs(const Options& options, const std::string& json, const std::string& table);

/// Where the per-backend traces go ("" for none): --out-dir, else with
/// --backend all next to --out or in the current directory.
std::filesystem::path benchTraceDirectory(const Options& options);

/// A CPU-track slice name that lives as long as the process (CpuEvent keeps
/// only the pointer, and the global profiler is never destroyed).
const char* internBenchName(const std::string& name);

/// Writes `profiler`'s events to `path` as a Chrome trace whose metadata
/// names `application` and the session's backend, device, driver and size.
Status writeBenchTrace(const profiler::Profiler& profiler, const std::string& path, const std::string& application,
                       const RenderSession& session);

} // namespace tessera::runtime
