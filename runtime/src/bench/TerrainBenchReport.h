#pragma once
/// @file TerrainBenchReport.h
/// The rows of `--bench terrain` (the first paper's Table 2: triangles drawn
/// and GPU time per mode, far away and close up) and their JSON and table.

#include <cstdint>
#include <string>
#include <vector>

namespace tessera::runtime {

/// One GPU pass of a row: median time over the measured frames and the
/// pipeline statistics of its median frame.
struct TerrainBenchPass {
    std::string name;
    double gpuMsMedian = 0.0;
    uint64_t clippingInvocations = 0;
    uint64_t vertexShaderInvocations = 0;
    uint64_t tessEvaluationInvocations = 0;
    uint64_t geometryShaderInvocations = 0;
    uint64_t fragmentShaderInvocations = 0;
};

struct TerrainBenchRecord {
    std::string backend;
    std::string mode;   ///< lowres | continuous | adaptive
    std::string view;   ///< far | close
    std::string look = "full"; ///< plain | full (backend::Look)
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
    double tessMax = 0.0; ///< largest adaptive level (0 for the other modes)

    /// Triangles of the backend's main terrain pass ("terrain.<mode>"):
    /// primitives generated for the clipper (clipping invocations, or the mesh
    /// primitives where a device counts none for mesh pipelines:
    /// profiler::generatedPrimitivesOf) in its median frame. The figure that
    /// is equal on every backend for the same levels.
    uint64_t clippingInvocations = 0;
    /// Sums over every pass of the median GPU frame.
    uint64_t vertexShaderInvocations = 0;
    uint64_t tessEvaluationInvocations = 0;
    uint64_t geometryShaderInvocations = 0;
    /// Fragment shader invocations over every pass of the median GPU frame,
    /// offscreen ones (the sun's and the characters' shadow maps) included:
    /// divided by width x height, the frame's fragments per pixel (its
    /// overdraw; issue 32's bound is 2 at 1280 x 720).
    uint64_t fragmentShaderInvocations = 0;
    /// Task and mesh shader invocations and the primitives the mesh shaders
    /// emitted (VK_EXT_mesh_shader's counters; 0 on the other backends).
    uint64_t taskShaderInvocations = 0;
    uint64_t meshShaderInvocations = 0;
    uint64_t meshPrimitives = 0;
    /// Bytes of the backend's intermediate buffers and render targets in the
    /// last frame (backend::FrameReport::intermediateBytes).
    uint64_t intermediateBytes = 0;
    /// Every GPU pass of the row, in first-recorded order.
    std::vector<TerrainBenchPass> passes;
    /// The Chrome trace holding this row's frames ("" when none was written).
    std::string trace;
};

/// The backend the comparison's ratios are taken against.
inline constexpr const char* kComparisonReference = "hulldomain";

/// The record of `reference` backend with the same device, view, mode, metric
/// and levels as `r`, or null.
const TerrainBenchRecord* matchingRecord(const std::vector<TerrainBenchRecord>& records, const TerrainBenchRecord& r,
                                         const std::string& reference);

/// JSON: a list of flat records (every value a string or a number), each
/// with backend, mode, view, width, height, triangles, gpu_ms_median,
/// gpu_ms_min, gpu_ms_max, device, and also driver, cpu_frame_ms_median,
/// patches, frames, metric, target_px, continuous_level, tess_max,
/// clipping_invocations, vertex_shader_invocations,
/// tess_evaluation_invocations, geometry_shader_invocations,
/// fragment_shader_invocations, fragments_per_pixel (the former over width x
/// height), intermediate_bytes, trace (the trace file or ""), passes (the
/// pass names, comma-separated) and per pass "pass:<name>:gpu_ms_median",
/// "pass:<name>:clipping_invocations", "pass:<name>:vertex_shader_invocations",
/// "pass:<name>:tess_evaluation_invocations",
/// "pass:<name>:geometry_shader_invocations" and
/// "pass:<name>:fragment_shader_invocations". Where the same run has a
/// hulldomain record of the same device, view, mode, metric and levels, also
/// gpu_ms_vs_hulldomain and clipping_invocations_vs_hulldomain (ratios).
std::string terrainBenchJson(const std::vector<TerrainBenchRecord>& records);

/// A table of the records, then per device, backend and view the ratios to
/// lowres of the same run: GPU time and triangles of continuous and of
/// adaptive with each metric.
std::string terrainBenchTable(const std::vector<TerrainBenchRecord>& records);

/// The backends side by side (--backend all): per device, view and mode,
/// one line per backend with GPU ms and triangles (clipping invocations of
/// the terrain pass) and their ratios to hulldomain, vertex,
/// tessellation-evaluation and geometry-shader invocations and intermediate
/// memory; then the median GPU ms of every pass. `notes` (skipped backends,
/// modes a backend does not draw) are printed under it.
std::string backendComparisonTable(const std::vector<TerrainBenchRecord>& records,
                                   const std::vector<std::string>& notes);

} // namespace tessera::runtime
