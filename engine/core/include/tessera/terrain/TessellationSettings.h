#pragma once
/// @file TessellationSettings.h
/// How terrain is tessellated: the paper's Table 2 modes and the adaptive
/// metrics, as the host chooses them per draw.

#include <cstdint>
#include <optional>
#include <string_view>

namespace tessera::terrain {

/// The first paper's Table 2 modes.
enum class TerrainMode : uint32_t {
    LowRes = 0,     ///< the untessellated control mesh
    Continuous = 1, ///< one tessellation level for the whole draw
    Adaptive = 2,   ///< per-edge levels from a metric
};

/// Per-edge metric of the adaptive mode (values match TS_METRIC_* in
/// engine/core/include/tessera/shaders/TessFactors.h, where the formulas live).
enum class TessMetric : uint32_t {
    ScreenEdge = 0,   ///< projected edge length against a pixel target
    Distance = 1,     ///< distance to the camera (paper, Listing 15)
    Silhouette = 2,   ///< finer where the surface turns away from the viewer
    HeightDetail = 3, ///< projected height-field error: flat ground coarse, ridges fine
};

struct TessellationSettings {
    TerrainMode mode = TerrainMode::Adaptive;
    TessMetric metric = TessMetric::ScreenEdge;
    /// Target edge length in pixels (screen, silhouette) or target error in
    /// pixels (detail); see defaultTargetPixels().
    float targetPixels = 16.0f;
    /// Distance metric: metres at which the level has fallen to minLevel.
    float farDistance = 4000.0f;
    /// Continuous mode's level for every edge.
    float continuousLevel = 15.0f;
    /// Clamp of adaptive levels; maxLevel is further clamped to the backend's maximum.
    float minLevel = 1.0f;
    float maxLevel = 64.0f;
};

/// The target each metric is tuned for when none is given: 16 px edges for
/// the screen and silhouette metrics (the peer sample uses 20), 2 px of
/// height-field error for the detail metric; unused by the distance metric.
constexpr float defaultTargetPixels(TessMetric metric) {
    return metric == TessMetric::HeightDetail ? 2.0f : 16.0f;
}

const char* toString(TerrainMode mode);
const char* toString(TessMetric metric);
/// "lowres", "continuous", "adaptive".
std::optional<TerrainMode> parseTerrainMode(std::string_view text);
/// "screen", "distance", "silhouette", "detail".
std::optional<TessMetric> parseTessMetric(std::string_view text);

} // namespace tessera::terrain
