#pragma once
/// @file CrowdRenderBenchReport.h
/// The figures of `--bench crowd` (the instanced crowd drawn on the terrain,
/// per crowd size and backend, and the terrain alone from the same camera)
/// and their JSON and table.

#include "bench/BenchSeries.h"
#include "tessera/lod/LodFrame.h"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tessera::runtime {

/// One backend drawing one crowd size (agents 0: the terrain alone).
struct CrowdRenderRow {
    std::string backend, device, driver;
    uint32_t agents = 0;
    uint32_t frames = 0; ///< measured frames
    /// Per measured frame, ms: the GPU passes summed, the CPU frame (wall
    /// time from beginFrame to endFrame), the crowd's simulation step, the
    /// LOD manager and building the instances.
    BenchSeries gpuFrame, cpuFrame, simulation, lod, instances;
    /// Median GPU ms per pass, in first-seen order.
    std::vector<std::pair<std::string, double>> passes;
    /// Medians of the crowd's passes, grouped: culling and binning (every
    /// crowd pass but the skin and the draws), the near tier's skinning, each
    /// tier's draw; and everything else (the terrain).
    double cullBinMs = 0.0, skinMs = 0.0, terrainMs = 0.0;
    std::array<double, lod::kTierCount> tierMs{};
    /// Per tier: instances the GPU drew (fading copies included; the
    /// backend's counts) and triangles (the tier's draw pass's clipping
    /// invocations: after tessellation), medians.
    std::array<double, lod::kTierCount> tierInstances{};
    std::array<double, lod::kTierCount> tierTriangles{};
    /// Per tier: agents in the frustum the terrain hid (horizon culling, the
    /// CPU reference's counts, by the tier their size would take), counted
    /// on the row's last frame.
    std::array<double, lod::kTierCount> tierHidden{};
    uint64_t crowdBytes = 0; ///< device memory of the crowd (FrameReport::crowdBytes)
    /// GPU passes whose timestamps cannot be trusted against the frame
    /// (lavapipe misses the rasterisation of some passes, and charges it to
    /// a later one): named, not charted.
    std::vector<std::string> suspectPasses;
    std::string camera; ///< the row's fixed view, "x,y,z,yaw,pitch"
    std::string trace;
};

struct CrowdRenderSummary {
    uint32_t width = 0, height = 0, warmupFrames = 0, frames = 0, meteors = 0;
    std::string camera; ///< how the views were chosen
    std::string terrain;
    std::vector<std::string> notes;
    std::vector<CrowdRenderRow> rows;
};

/// "format": "tessera-bench-crowd", "version": 1, the settings, and "rows":
/// one object per (crowd size, backend) with the series as {"median",
/// "mean", "min", "max"}, the passes, the tiers, memory per agent and the
/// ratios to hulldomain's row and to the backend's terrain-alone row.
std::string crowdRenderBenchJson(const CrowdRenderSummary& summary);

/// The same as a table: one line per row, then the ratios.
std::string crowdRenderBenchTable(const CrowdRenderSummary& summary);

} // namespace tessera::runtime
