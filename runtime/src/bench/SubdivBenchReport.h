#pragma once
/// @file SubdivBenchReport.h
/// The rows and figures of `--bench subdiv` and their JSON and table.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tessera::runtime {

/// One measured configuration on one backend.
struct SubdivBenchRow {
    std::string backend, device, driver;
    std::string variant;  ///< base | displaced | displaced-lod | weingarten
    double level = 0.0;   ///< the fixed level (0: adaptive)
    double gpuMsMedian = 0.0, gpuMsMin = 0.0, gpuMsMax = 0.0; ///< the subdivision passes
    double gpuFrameMsMedian = 0.0;
    uint32_t frames = 0;
    uint64_t triangles = 0;       ///< the CPU reference's prediction (what the draws tessellate)
    uint64_t clipped = 0;         ///< clipping invocations of the draw pass (pipeline statistics), 0 if none
    uint32_t domains = 0;
    std::vector<std::pair<std::string, double>> passes; ///< median GPU ms per subdivision pass
    std::string trace;
};

/// Memory of the displacement, per representation, for the same samples.
struct SubdivMemory {
    uint64_t coefficients = 0;   ///< tile samples (level 0 interiors)
    uint64_t tileBytes = 0;      ///< the packed texture (overlaps, mips, packing) plus 16-byte records
    uint64_t denseMeshBytes = 0; ///< a mesh with a vertex per sample: position and normal (24 B) and 6 indices
    uint64_t atlasBytes = 0;     ///< R16 displacement + RGBA8 normal map per sample, at 70% atlas coverage, with mips
};

struct SubdivBenchSummary {
    uint32_t width = 0, height = 0, warmupFrames = 0, frames = 0;
    std::vector<std::string> surfaces;
    SubdivMemory memory;
    std::vector<SubdivBenchRow> rows;
    std::vector<std::string> notes;
};

std::string subdivBenchJson(const SubdivBenchSummary& summary);
std::string subdivBenchTable(const SubdivBenchSummary& summary);

} // namespace tessera::runtime
