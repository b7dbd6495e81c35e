#pragma once
/// @file TerrainBenchReport.h
/// The rows of `--bench terrain` (the first paper's Table 2: triangles drawn
/// and GPU time per mode, far away and close up) and their JSON and table.

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::demo {

struct TerrainBenchRecord {
    std::string backend;
    std::string mode;   ///< lowres | continuous | adaptive
    std::string view;   ///< far | close
    std::string device;
    std::string driver;
    uint32_t width = 0;
    uint32_t height = 0;
    /// Triangles reaching the clipper in the median frame (pipeline statistics;
    /// 0 where the device has none).
    uint64_t triangles = 0;
    uint32_t patches = 0; ///< visible patches drawn per frame
    double gpuMsMedian = 0.0, gpuMsMin = 0.0, gpuMsMax = 0.0;
    /// Median CPU frame time (recording, submission and, on a CPU device
    /// such as lavapipe, the wait for the previous frame): the figure to set
    /// against a whole-frame time measured elsewhere.
    double cpuFrameMsMedian = 0.0;
    uint32_t frames = 0;
    std::string metric;   ///< adaptive metric ("-" for the other modes)
    double targetPixels = 0.0;
    double continuousLevel = 0.0;
};

/// JSON: a list of records, each with backend, mode, view, width, height,
/// triangles, gpu_ms_median, gpu_ms_min, gpu_ms_max, device, and also driver,
/// cpu_frame_ms_median, patches, frames, metric, target_px and
/// continuous_level.
std::string terrainBenchJson(const std::vector<TerrainBenchRecord>& records);

/// A table of the records, then per device, backend and view the ratios to
/// lowres of the same run: GPU time and triangles of continuous and of
/// adaptive with each metric.
std::string terrainBenchTable(const std::vector<TerrainBenchRecord>& records);

} // namespace tessera::demo
