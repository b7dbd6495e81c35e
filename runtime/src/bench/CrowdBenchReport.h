#pragma once
/// @file CrowdBenchReport.h
/// The figures of `--bench crowd-sim` (the crowd simulation on the CPU: step
/// time per phase, memory, overlaps and behaviour under a meteor shower, per
/// crowd size) and their JSON and table.

#include "bench/BenchSeries.h"
#include "tessera/crowd/CrowdStats.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::runtime {

/// One crowd size, from creation to its last measured step.
struct CrowdBenchRun {
    uint32_t agents = 0;
    std::string layout;    ///< describeLayout()
    double createMs = 0.0; ///< Crowd::create (navigation, spawn, the fields' first solve)
    /// Per measured step, ms: crowd::CrowdTimings' total and phases, and the
    /// wall time around step() (the total plus what no phase covers).
    BenchSeries total, fields, avoidance, integration, wall;
    double bytesPerAgent = 0.0; ///< crowd::CrowdMemory after the last step
    uint64_t agentBytes = 0, fieldBytes = 0;
    crowd::OverlapReport overlapEnd;   ///< measureOverlap() after the last step
    crowd::OverlapReport overlapWorst; ///< the largest of each figure over the sampled steps
    uint32_t overlapSamples = 0;
    uint64_t arrivals = 0;
    uint32_t walkingEnd = 0, stuckEnd = 0, stuckMax = 0, fleeingEnd = 0, fleeingMax = 0, unreachableEnd = 0;
    float maxStuckSeconds = 0.0f;      ///< the longest any agent was stuck, at the end
    double fieldTilesSolvedMean = 0.0; ///< tile solves per measured step
    uint32_t fieldTilesWaitingEnd = 0;
    uint32_t impacts = 0;          ///< craters landed (warm-up included)
    double simulatedSeconds = 0.0; ///< warm-up and measured steps
};

struct CrowdBenchSummary {
    std::string cpuModel;
    uint32_t cpuCores = 0;        ///< logical processors online
    uint32_t threads = 0;         ///< the crowd's threads (--threads, else core::hardwareThreads())
    uint32_t hardwareThreads = 0; ///< core::hardwareThreads()
    std::string terrain;          ///< the height map's file
    float terrainWidth = 0.0f, terrainDepth = 0.0f, cellSize = 0.0f;
    double timeStep = 0.0;
    uint32_t warmupSteps = 0, steps = 0, overlapEvery = 0;
    double meteorIntervalSeconds = 0.0;
    uint32_t seed = 0;
    uint32_t goalGroups = 0;
    float goalDistance = 0.0f;
    float radiusMin = 0.0f, radiusMax = 0.0f, speedMin = 0.0f, speedMax = 0.0f;
    std::vector<CrowdBenchRun> runs;
};

/// A JSON object: "format": "tessera-bench-crowd-sim", "version": 1, the
/// machine and the run's settings, and "runs": one object per crowd size
/// with "step_ms", "fields_ms", "avoidance_ms", "integration_ms" and
/// "wall_ms" as {"median", "mean", "max"}, memory, "overlap_end",
/// "overlap_worst_sampled" and the behaviour counts.
std::string crowdBenchJson(const CrowdBenchSummary& summary);

/// The same figures as a readable table, one row per crowd size.
std::string crowdBenchTable(const CrowdBenchSummary& summary);

} // namespace tessera::runtime
