#pragma once
/// @file BenchInput.h
/// What the comparison report reads: the records of `tessera-demo --bench
/// terrain --backend all` (docs/BACKENDS.md, "What the columns mean"), read
/// back from their JSON, and the folder layout of a report's inputs.
///
/// Every reader fails with one line that names the file and the problem
/// ("bench.json: malformed JSON at byte 12: ...", "bench.json: record 3 has
/// no \"backend\""), never with an exception or a crash.

#include "tessera/core/Result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tessera::report {

/// One GPU pass of a record: its median time.
struct PassTime {
    std::string name;
    double gpuMs = 0.0;
};

/// One record of the terrain benchmark: a backend drawing one view in one
/// mode (and metric) on one device.
struct BenchRecord {
    std::string backend;
    std::string device;
    std::string driver;
    std::string view;   ///< far | close
    std::string mode;   ///< lowres | continuous | adaptive
    std::string metric; ///< the adaptive metric, "-" otherwise
    uint32_t width = 0;
    uint32_t height = 0;
    double gpuMs = 0.0;      ///< gpu_ms_median: the sum of every pass
    double cpuFrameMs = 0.0; ///< cpu_frame_ms_median: the wall-clock frame
    uint64_t triangles = 0;  ///< clipping_invocations of the main terrain pass
    uint64_t vertexShaderInvocations = 0;
    uint64_t tessEvaluationInvocations = 0;
    uint64_t geometryShaderInvocations = 0;
    uint64_t taskShaderInvocations = 0; ///< task and mesh: the meshshader backend's
    uint64_t meshShaderInvocations = 0;
    uint64_t intermediateBytes = 0;
    std::vector<PassTime> passes; ///< in the order of the record's "passes"
    std::string trace;            ///< the trace file the run named ("" if none)

    /// "far adaptive/detail": the row's name, as the benchmark's trace slices
    /// and tables call it.
    std::string rowLabel() const;
    /// The name of the main terrain pass, "terrain.<mode>": the pass that
    /// draws the frame's triangles.
    std::string mainPassName() const { return "terrain." + mode; }
};

/// Reads `path`, a JSON array of terrain benchmark records. Fails, naming the
/// file, when it is missing, unreadable, not JSON, not an array, empty, or a
/// record lacks a key the report needs or holds one of the wrong type.
Result<std::vector<BenchRecord>> loadBenchRecords(const std::filesystem::path& path);

/// The same, from text already read (`name` names it in messages).
Result<std::vector<BenchRecord>> parseBenchRecords(const std::string& text, const std::string& name);

/// The backends of `records` in the report's order: hulldomain (the
/// reference) first, then the others in order of first appearance.
std::vector<std::string> backendsOf(const std::vector<BenchRecord>& records);

/// Where a report's inputs lie in its folder (the names `--run` writes).
struct InputLayout {
    std::filesystem::path dir;
    std::filesystem::path bench() const { return dir / "bench.json"; }
    /// The per-backend Chrome trace the benchmark writes with --out-dir.
    std::filesystem::path trace(const std::string& backend) const { return dir / ("bench-" + backend + ".json"); }
    std::filesystem::path screenshot(const std::string& backend) const {
        return dir / ("screenshot-" + backend + ".png");
    }
};

} // namespace tessera::report
