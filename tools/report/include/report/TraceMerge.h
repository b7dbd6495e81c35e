#pragma once
/// @file TraceMerge.h
/// One Chrome/Perfetto trace holding every backend's benchmark trace, one
/// process track per backend.

#include "tessera/core/Result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace tessera::report {

/// One backend's trace to merge.
struct TraceSource {
    std::string backend;
    std::filesystem::path path;
};

/// Summary of a merge, for the report.
struct MergedTrace {
    std::string json;                  ///< the merged trace's text
    size_t events = 0;                 ///< events written (metadata included)
    std::vector<std::string> backends; ///< in pid order (pid 1, 2, ...)
};

/// Merges the traces. Backend i becomes process i + 1, named after the
/// backend and its device (a `process_name` metadata event, with
/// `process_sort_index` i), its threads keep their ids and names. Every
/// trace is shifted to start at 0: traces from separate runs share no clock,
/// and aligned starts put the backends' identical row sequences side by side.
/// Fails naming the file when one is missing or is not a Chrome trace
/// (an object with a "traceEvents" array, or a bare array of events).
Result<MergedTrace> mergeTraces(const std::vector<TraceSource>& sources);

} // namespace tessera::report
